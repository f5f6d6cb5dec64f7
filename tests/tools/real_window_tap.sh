#!/bin/sh
# A tap of any length is never lost: in a real window under Xvfb, Space pressed and released in
# the same instant (xdotool sends both at once, well under a frame apart) must still be a jump: the
# run's recording holds a frame with jump held, and the game heard it. Before, the game read the
# keys' state once a frame, and a tap between two reads never happened. Run by ctest as
#   with_xvfb.sh real_window_tap.sh PLATON
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
folder=$(mktemp -d)
log="$folder/log"
"$platon" play levels/cube_intro/scene.lua --record "$folder/tap.replay" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; rm -rf "$folder"; exit 1; }
. "$(dirname "$0")/window_test.sh"
focus_window
await "^frame 1: "  # the level plays
for _ in 1 2 3; do
  xdotool keydown space keyup space
  sleep 0.5
done
xdotool key Escape
await_exit "Esc did not end the play"
wait "$pid" || fail "play failed"
grep -q "jump" "$folder/tap.replay" || fail "three taps of Space, none in the recording: $(cat "$folder/tap.replay" | head -12)"
taps=$(sed -n '/^input$/,/^end$/p' "$folder/tap.replay" | grep -c "jump" || true)
[ "$taps" -ge 3 ] || fail "three taps of Space, $taps in the recording"
cat "$log"
rm -rf "$folder"
