#!/bin/sh
# The level editor in a real window (Xvfb; the mouse and keys by xdotool), once per solid: a new
# level (`platon edit --new SOLID`: a start and a goal, no floor) gets its floor drawn with the
# mouse; the draw is undone and redone; the start put into the floor is shown as an error and its
# save refused; the level is saved (its comments kept), checked by `platon check`, played from the
# cursor in the same window and finished by holding Right; K keeps the run as a test beside the
# level, which `platon run` passes, the lint passes, `pack` packs, `install` installs (its run
# replays) and the game's title lists under "your levels". Run by ctest as
#   with_xvfb.sh real_window_editor.sh PLATON SOLID [SCREENSHOT_FOLDER]
# With a folder, F12's pictures of the drawn floor, the refused start and the finished play-test are
# copied there (editor_draw.png, editor_error.png, editor_play.png: docs/editing.md's).
set -eu
platon=$(realpath "$1")
source_root=$(pwd)  # ctest runs it from the source tree: its .luacheckrc is the lint
solid=$2
pictures=${3:-}
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
level="$data/drawn"
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -rf "$data"; exit 1; }
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" edit --new "$solid" "$level" > "$log" 2>&1 &
pid=$!
. "$(dirname "$0")/window_test.sh"
. "$(dirname "$0")/editor_probe.sh"
shots=0
# shot NAME: F12, and the picture copied to the screenshot folder (when one was given).
shot() {
  [ -n "$pictures" ] || return 0
  xdotool key F12
  shots=$((shots + 1))
  await "^screenshot: " "$shots"
  cp "$(grep "^screenshot: " "$log" | sed -n "${shots}p" | cut -c13-)" "$pictures/$1.png"
}
focus_window
await "^editing "

probe_face0
start_x=$(awk 'NR>1 && /# start/ {print $2}' "$level/drawn.level")
goal_x=$(awk 'NR>1 && /# goal/ {print $2}' "$level/drawn.level")
[ "$(pixel 0 0)" != "off" ] || fail "the probing presses were not all on face 0: $map"

# The floor, dragged with the left button in the draw tool; undone and redone.
xdotool key d
drag $((start_x - 300)) 256 $((goal_x + 300)) 256
await "^editor: draw a segment"
xdotool key ctrl+z
await "^editor: undone: draw a segment"
xdotool key ctrl+y
await "^editor: redone: draw a segment"
shot editor_draw

# The start onto the floor: an error where the start is; the save refused; undone.
point "$start_x" 280
xdotool key p
await "^editor: move the start"
xdotool key ctrl+s
await "^editor: not saved: the level would not load"
shot editor_error
xdotool key ctrl+z
await "^editor: undone: move the start"

xdotool key ctrl+s
await "^editor: saved "
grep -q "^# drawn: made by" "$level/drawn.level" || fail "the saved level lost its comments: $(cat "$level/drawn.level")"
grep -q "# face 0: draw a floor" "$level/drawn.level" || fail "the saved level lost a face's comment"
"$platon" check "$level" > "$data/check" 2>&1 || fail "platon check refused the drawn level: $(cat "$data/check")"

# Play from the cursor (on the start), hold Right to the goal, keep the run as a test.
point "$start_x" 420
xdotool key Return
await "^playing from face 0"
xdotool keydown Right
await "^goal reached at frame"
xdotool keyup Right
shot editor_play
xdotool key k
await "^kept as .*passes headless"
xdotool key Escape
await "^editor: kept as "
xdotool key Escape
await_exit "Esc did not quit the editor"
wait "$pid" || fail "the editor failed"
(cd "$level" && "$platon" run test_1.lua) > "$data/run" 2>&1 || fail "the kept test does not pass: $(cat "$data/run")"
grep -q "^  start = { face = 0" "$level/test_1.lua" || fail "the kept test does not start where the run did"
# The modder's next steps: the kept test passes the project's lint, and packs as the level's run.
(cd "$source_root" && luacheck --no-color --codes --config .luacheckrc "$level/test_1.lua") > "$data/lint" 2>&1 ||
  fail "the kept test fails the lint: $(cat "$data/lint")"
"$platon" pack "$level" --replay "$level/test_1.lua" -o "$data/drawn.platon" > "$data/pack" 2>&1 ||
  fail "pack refused the kept test: $(cat "$data/pack")"
# Installed into the player's levels (as someone who got the package would), its run replays, and
# the game's title screen lists it under "your levels", after the campaign, in the same window system.
XDG_DATA_HOME="$data/player" "$platon" install "$data/drawn.platon" > "$data/install" 2>&1 ||
  fail "install refused the package: $(cat "$data/install")"
"$platon" replay "$data/player/platon/levels/drawn/finish.replay" > "$data/replayed" 2>&1 ||
  fail "the installed run does not replay: $(cat "$data/replayed")"
log="$data/game_log"
PLATON_PRINT_SCREEN=1 XDG_DATA_HOME="$data/player" XDG_CONFIG_HOME="$data/config" "$platon" game > "$log" 2>&1 &
pid=$!
await_title
await "^screen> your levels:"
campaign=$(sed 's/#.*//' "$source_root/levels/campaign.txt" | grep -c '[^[:space:]]')
await "^screen>   $((campaign + 1))\. "
xdotool key Escape  # quit? asks
await "^quit asked"
xdotool key Return
await_exit "the game did not quit"
wait "$pid" || fail "the game failed"
cat "$log"
rm -rf "$data"
