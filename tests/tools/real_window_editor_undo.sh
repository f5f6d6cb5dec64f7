#!/bin/sh
# Every kind of edit in the editor's real window (Xvfb; mouse and keys by xdotool) on a copy of
# cube_switches, a file full of comments: draw, move an end, move a segment, tag, number, one-way,
# copy and paste, delete, the start, the goal, a face's gravity. Saved, the file keeps every
# comment of a line that is still there; then each edit is undone (Ctrl+Z), and saved again the
# file is the original byte for byte; redone (Ctrl+Y), it is the edited one again. Run by ctest as
#   with_xvfb.sh real_window_editor_undo.sh PLATON
set -eu
platon=$(realpath "$1")
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
cp -r levels/cube_switches "$data/cube_switches"
file="$data/cube_switches/cube_switches.level"
cp "$file" "$data/original.level"
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; rm -rf "$data"; exit 1; }
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" edit "$data/cube_switches" > "$log" 2>&1 &
pid=$!
. "$(dirname "$0")/window_test.sh"
. "$(dirname "$0")/editor_probe.sh"
focus_window
await "^editing "
probe_face0
[ "$(pixel 0 0)" != "off" ] || fail "the probing presses were not all on face 0: $map"
edits=0
# edit MESSAGE: waits for the editor to say it made that edit.
edit() {
  edits=$((edits + 1))
  await "^editor: $1"
}
xdotool key d
drag 2600 2400 3400 2400  # a new shelf
edit "draw a segment"
xdotool key s
drag 3400 2400 3400 2600  # its right end
edit "move an end point"
drag 3000 2500 3000 2300  # the whole of it (a press on its middle)
edit "move a segment"
xdotool key t  # selected: it becomes a hazard
edit "tag 1 segment hazard"
xdotool key t t t bracketright  # through the palette to a door, then door 2
edit "tag 1 segment goal"
edit "tag 1 segment checkpoint"
edit "tag 1 segment door 1"
edit "tag 1 segment door 2"
xdotool key o
edit "one-way on or off"
xdotool key ctrl+c
point 2400 3200
xdotool key ctrl+v
edit "paste 1 segment"
xdotool key Delete  # the pasted copy (selected)
edit "delete a segment"
point 900 1500
xdotool key p
edit "move the start"
point 2000 2000
xdotool key g
edit "move the goal"
xdotool key v
edit "face 0's gravity right"
xdotool key ctrl+s
await "^editor: saved "
grep -q "door 2" "$file" || fail "the saved level has not the edits: $(cat "$file")"
grep '#' "$data/original.level" | while IFS= read -r line; do
  grep -qF -- "${line#*#}" "$file" || fail "a comment went: $line"
done
cp "$file" "$data/edited.level"
i=0
while [ "$i" -lt "$edits" ]; do
  xdotool key ctrl+z
  i=$((i + 1))
  await "^editor: undone: " "$i"
done
xdotool key ctrl+s
await "^editor: saved " 2
cmp "$file" "$data/original.level" || fail "after every undo the file is not the original: $(diff "$data/original.level" "$file")"
i=0
while [ "$i" -lt "$edits" ]; do
  xdotool key ctrl+y
  i=$((i + 1))
  await "^editor: redone: " "$i"
done
xdotool key ctrl+s
await "^editor: saved " 3
cmp "$file" "$data/edited.level" || fail "after every redo the file is not the edited one"
xdotool key Escape
await_exit "Esc did not quit the editor"
wait "$pid" || fail "the editor failed"
cat "$log"
rm -rf "$data"
