#!/bin/sh
# The game prints a script error once, not on every frame it repeats (60 tracebacks a second), and
# again when it changes. A one-level campaign whose level errors on every frame is played in a real
# window (Xvfb, keys typed with xdotool) until the second error. Run by ctest as
#   with_xvfb.sh game_frame_errors.sh PLATON
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
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
  if frame < 180 then error("another error from frame 120 on") end
  game.message("frame " .. frame)
end
return level
LUA
XDG_DATA_HOME="$data" "$platon" game --campaign "$data/levels/campaign.txt" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
await_title
xdotool key Return
await "^playing broken"
await "another error from frame 120 on"
xdotool key Escape Down Down Down Down Return Return  # the pause menu: Quit, and yes
await_exit "Quit did not end the game"
wait "$pid" || fail "the game failed"
first=$(grep -c "the same error every frame" "$log" || true)
second=$(grep -c "another error from frame 120 on" "$log" || true)
[ "$first" -eq 1 ] || fail "the first error was printed $first times"
[ "$second" -eq 1 ] || fail "the second error was printed $second times"
echo "each error printed once"
rm -rf "$data"
