#!/bin/sh
# A real window under Xvfb, keys typed with xdotool: holding Right must walk the player of the
# first level to its goal (with no key it would stand at the start for ever), where the play ends
# by itself (play's help: "default: at the goal"). Run by ctest as
#   with_xvfb.sh real_window_keys.sh PLATON
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
log=$(mktemp)
"$platon" play levels/cube_intro/scene.lua > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -f "$log"; exit 1; }
. "$(dirname "$0")/window_test.sh"
focus_window
xdotool keydown Right
await "^goal reached at frame"
xdotool keyup Right
await_exit "the play did not end at the goal"
wait "$pid" || fail "play failed"
cat "$log"
rm -f "$log"
