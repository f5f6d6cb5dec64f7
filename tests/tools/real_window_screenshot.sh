#!/bin/sh
# F12 in a real window under Xvfb: the frame on screen saved as a PNG in the player's data folder
# (screenshots/, made when missing), two in one second under two names, and the title's settings
# screen shot the same way. Run by ctest as
#   with_xvfb.sh real_window_screenshot.sh PLATON [COPY_SETTINGS_TO]
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" game > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
await_title
xdotool key F12
await "^screenshot: "
xdotool key Tab  # the settings
xdotool key F12
await "^screenshot: " 2
xdotool key Escape Escape Return  # back to the title, quit, and yes
await_exit "Esc on the title did not end the game"
wait "$pid" || fail "the game failed"
shots=$(ls "$data/platon/screenshots" | wc -l)
[ "$shots" -eq 2 ] || fail "$shots screenshots, not 2: $(ls "$data/platon/screenshots")"
for f in "$data"/platon/screenshots/*.png; do
  [ "$(head -c 8 "$f" | od -An -c | tr -d ' ')" = '211PNG\r\n032\n' ] || fail "$f is no PNG"
  [ "$(stat -c %s "$f")" -gt 2000 ] || fail "$f is nearly empty"
done
settings=$(grep "^screenshot: " "$log" | sed -n 2p | cut -c13-)
[ -n "${2:-}" ] && cp "$settings" "$2"
cat "$log"
rm -rf "$data"
