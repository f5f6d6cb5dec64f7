#!/bin/sh
# A mod author's journey, in `platon play`'s real window (Xvfb, keys typed with xdotool): a mod
# with a tag whose handler acts on a resting player (a conveyor, from the mod's tick through the
# player's contacts, as docs/scripting.md says) and an action of its own (the docs' dash, on Left
# Shift, with the level's player that uses it). The belt carries the player standing still; Left
# Shift dashes (the window binds the mod's action); the console answers; F5 reloads the mod; the
# recording holds "dash" by name and replays bit for bit. Run by ctest as
#   with_xvfb.sh journey_mod_author.sh PLATON
set -eu
platon=$1
here=$(cd "$(dirname "$0")" && pwd)
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
level="$data/belt"
mkdir -p "$level"
printf 'HEXAHEDRON\n0 600 700\n2 2000 800\n4096\n%%\n0 512 1800 512 conveyor\n1800 512 4096 512\n3600 513 3600 1200 goal\n%%\n0 512 4096 512\n%%\n0 512 4096 512\n%%\n0 512 4096 512\n%%\n%%\n' > "$level/belt.level"
cat > "$level/belt.lua" <<'LUA'
local CONVEYOR
local said = false
return { tags = { conveyor = { color = "#56b4e9" } },
  actions = { dash = { keys = { "Left Shift" }, pad = { "x" }, label = "Dash", does = "a burst along the face" } },
  tick = function(game)
    CONVEYOR = CONVEYOR or platon.tags.conveyor
    local w, p = game.world, game.player()
    if not p then return end
    for i = 1, w.contactCount(p) do
      local _, _, tag = w.contact(p, i)
      if tag == CONVEYOR then
        local _, vy = w.velocity(p)
        w.setVelocity(p, 5, vy)
      end
    end
    local _, x = w.position(p)
    if x > 1700 and not said then
      said = true
      game.message("carried by the belt")
    end
  end }
LUA
sed -n '/^## Actions$/,/^## The player$/p' docs/scripting.md | sed -n '/^```lua player$/,/^```$/p' | sed '1d;$d' > "$level/player.lua"
grep -q "Player.move" "$level/player.lua" || { echo "the docs' dash player is gone"; exit 1; }
# The player says when it dashes (its game's message).
sed -i 's/^    self.dashed = not self.grounded.*/&\n    game.message = "dashed"/' "$level/player.lua"
sed -i 's/^local _, Player = .*/local game, Player = .../' "$level/player.lua"
cat > "$level/scene.lua" <<'LUA'
return { name = "belt", systems = { "scripting", "rendering", "audio" }, stage = { level = "belt.level" },
  gravity = 0.35, scripts = { preset = "game", player = "player.lua", mods = { "belt.lua" } } }
LUA
cd "$data"
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" play belt --record "$data/run.replay" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right shift 2>/dev/null; rm -rf "$data"; exit 1; }
. "$here/window_test.sh"
focus_window
await "^playing "
await "^frame [0-9]*: carried by the belt"  # no key held: the belt's tick moved the standing player
xdotool keydown Right
sleep 0.3
xdotool key shift  # Left Shift: the mod's action
await "^frame [0-9]*: dashed"
xdotool keyup Right
xdotool key grave
xdotool type --delay 20 'platon.tags.conveyor >= 1000000'
xdotool key Return
await "^true$"
xdotool key grave
xdotool key F5
await "^reloaded in "
await "^recording stops at frame "
xdotool keydown Right
await "^goal reached at frame "
xdotool keyup Right
await_exit "play did not end at the goal"
wait "$pid" || fail "play failed"
grep -qE "^[0-9]+ .*dash" "$data/run.replay" || fail "the recording holds no dash: $(cat "$data/run.replay")"
"$platon" replay "$data/run.replay" > "$data/replayed" 2>&1 || fail "the recording differs: $(cat "$data/replayed")"
echo "a mod author's journey: a belt that carries a resting player, a dash on its own key, the console, F5"
rm -rf "$data"
