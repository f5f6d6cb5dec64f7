#!/bin/sh
# A player's keys and the assist mode, from the settings file, in a real window under Xvfb: with
# "right" bound to L (and the arrows no longer), holding L walks the first level to its goal. Then,
# at a game speed of 50 %, a run of the next level is recorded with its speed and replays bit for bit
# headless (the assist mode slows the pace, never the frames). Run by ctest as
#   with_xvfb.sh real_window_remap.sh PLATON
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
mkdir -p "$data/config/platon"
# Names no key has: each is said, and a button left with none keeps its default (Jump: Space).
printf 'keys_right L\nkeys_left Left, Bogus\nkeys_jump Nonsense, AlsoNot\ngame_speed 100\n' > "$data/config/platon/settings.txt"
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" game --record "$data/runs" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup l 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
await_title
grep -q "no key or pad button is named 'Bogus'$" "$log" || fail "Bogus was not said (or Left lost its default)"
grep -q "no key or pad button is named 'Nonsense'$" "$log" || fail "Nonsense was not said"
grep -q "no key or pad button is named 'AlsoNot'; Jump keeps its default (Space)$" "$log" ||
  fail "Jump did not keep its default"
xdotool key Return
await "^playing cube_intro"
xdotool keydown l
await "^level complete: cube_intro"
xdotool keyup l
xdotool key Escape  # the level select
xdotool key Escape Return  # quit, and yes
await_exit "Esc on the title did not end the game"
wait "$pid" || fail "the game failed"
grep -q "^right" "$data/runs/cube_intro.replay" || grep -q " right" "$data/runs/cube_intro.replay" ||
  fail "the recording holds no right: $(head -12 "$data/runs/cube_intro.replay")"

# The assist mode at 50 %: a few seconds of the next level, recorded with its speed.
printf 'keys_right L\ngame_speed 50\n' > "$data/config/platon/settings.txt"
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" game --record "$data/slow" > "$log" 2>&1 &
pid=$!
await_title
xdotool key Return
await "^playing tetra_around"
xdotool keydown l
sleep 2
xdotool keyup l
xdotool key Escape Down Down Down Down Return Return  # the pause menu: Quit, and yes
await_exit "Quit in the pause menu did not end the game"
wait "$pid" || fail "the game failed"
grep -q "^speed 50$" "$data/slow/tetra_around.replay" || fail "the slowed run does not say its speed: $(head -6 "$data/slow/tetra_around.replay")"
"$platon" replay "$data/slow/tetra_around.replay" > "$log" 2>&1 || fail "the slowed run does not replay"
cat "$log"
rm -rf "$data"
