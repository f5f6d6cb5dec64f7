#!/bin/sh
# With no display to open (neither DISPLAY nor WAYLAND_DISPLAY set, or DISPLAY a server that is not there) and no
# SDL_VIDEODRIVER asked for, the window commands say so and end (the game, the editor), or say so
# and go on headless (play); none runs without a window where nobody sees it.
#   no_display.sh PLATON
set -u
platon=$1
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
unset SDL_VIDEODRIVER WAYLAND_DISPLAY
failed=0
# expect NAME STATUS PATTERN COMMAND...: runs the command (8 s at most), checks its exit status
# ("nonzero" or "zero") and that its output has PATTERN.
expect() {
  name=$1 want=$2 pattern=$3
  shift 3
  out=$(XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" timeout 8 "$@" 2>&1)
  status=$?
  if [ "$status" -eq 124 ] || { [ "$want" = nonzero ] && [ "$status" -eq 0 ]; } ||
    { [ "$want" = zero ] && [ "$status" -ne 0 ]; } || ! printf '%s\n' "$out" | grep -q -- "$pattern"; then
    echo "$name: exit $status, wanted $want and '$pattern'; it printed:"
    printf '%s\n' "$out" | grep -v "^ALSA" | head -5
    failed=1
  fi
}
for display in "" ":97"; do
  if [ -n "$display" ]; then export DISPLAY="$display"; else unset DISPLAY; fi
  what=${display:+DISPLAY=$display could not be opened}
  what=${what:-neither DISPLAY nor WAYLAND_DISPLAY is set}
  expect "game, $what" nonzero "no display to open a window on ($what" "$platon" game
  expect "edit, $what" nonzero "no display to open a window on ($what" "$platon" edit --new HEXAHEDRON "$data/new$display"
  expect "play, $what" zero "no display to open a window on ($what.*playing headless" \
    "$platon" play levels/cube_switches/scene.lua --frames 30
done
exit "$failed"
