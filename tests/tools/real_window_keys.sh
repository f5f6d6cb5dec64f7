#!/bin/sh
# A real window under Xvfb, keys typed with xdotool: holding Right must move the player, so the
# run's state hash differs from the same number of frames with no key held (600 frames, 10 s: room
# for a loaded machine to show the window and take the key). Run by ctest as
#   xvfb-run -a real_window_keys.sh PLATON
set -eu
platon=$1
unset SDL_VIDEODRIVER  # the X server xvfb-run started, not offscreen
log=$(mktemp)
"$platon" play levels/cube_intro/scene.lua --frames 600 > "$log" 2>&1 &
pid=$!
. "$(dirname "$0")/focus_window.sh"
focus_window || { echo "no window appeared"; cat "$log"; kill "$pid"; exit 1; }
xdotool keydown Right
wait "$pid" || { cat "$log"; exit 1; }
xdotool keyup Right 2>/dev/null || true
played=$(tail -n 1 "$log")
idle=$("$platon" play levels/cube_intro/scene.lua --frames 600 --headless --fast | tail -n 1)
echo "keys held: $played"
echo "no keys:   $idle"
rm -f "$log"
case "$played" in "state hash "*) ;; *) echo "the game printed no state hash"; exit 1 ;; esac
[ "$played" != "$idle" ] || { echo "the keys typed into the window did not move the player"; exit 1; }
