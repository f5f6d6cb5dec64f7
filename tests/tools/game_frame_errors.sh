#!/bin/sh
# The game prints a script error once, not on every frame it repeats (60 tracebacks a second), and
# again when it changes. A one-level campaign whose level errors on every frame is played for a
# second in a real window (Xvfb, keys typed with xdotool). Run by ctest as
#   with_xvfb.sh game_frame_errors.sh PLATON
set -eu
platon=$1
unset SDL_VIDEODRIVER  # the X server xvfb-run started, not offscreen
data=$(mktemp -d)
log="$data/log"
mkdir -p "$data/levels/broken"
echo "broken" > "$data/levels/campaign.txt"
cat > "$data/levels/broken/scene.lua" <<'LUA'
return { name = "Broken", systems = { "scripting", "rendering" }, stage = { solid = "cube", edge = 4096 },
  scripts = { preset = "game", level = "level.lua" } }
LUA
cat > "$data/levels/broken/level.lua" <<'LUA'
local level = { start = { face = 0, x = 600, y = 700 } }
function level.build(game) game.world.line(0, 0, 512, 4096, 512) end
function level.tick(game, frame)
  if frame < 120 then error("the same error every frame") end
  error("another error from frame 120 on")
end
return level
LUA
XDG_DATA_HOME="$data" "$platon" game --campaign "$data/levels/campaign.txt" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/focus_window.sh"
focus_window || fail "no window appeared"
sleep 0.3
xdotool key Return
for _ in $(seq 100); do grep -q "^playing broken" "$log" && break; sleep 0.1; done
grep -q "^playing broken" "$log" || fail "Enter did not start the level"
sleep 3  # 180 frames: 119 of the first error, then the second
xdotool key Escape
sleep 0.3
xdotool key Down Down Down Return  # Quit
for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$pid" 2>/dev/null && fail "Quit did not end the game"
wait "$pid" || fail "the game failed"
first=$(grep -c "the same error every frame" "$log" || true)
second=$(grep -c "another error from frame 120 on" "$log" || true)
[ "$first" -eq 1 ] || fail "the first error was printed $first times"
[ "$second" -eq 1 ] || fail "the second error was printed $second times"
echo "each error printed once"
rm -rf "$data"
