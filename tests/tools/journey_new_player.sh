#!/bin/sh
# A new player's journey, in a real window (Xvfb, keys typed with xdotool), asserted on what the
# screen says (PLATON_PRINT_SCREEN prints its text as it changes) and on the files: the title with
# level 2 locked -> level 1 played to its goal -> the title with level 2 open -> the settings,
# Jump moved to K -> level 2, jumping with K (its recording holds "jump" and replays bit for bit)
# -> quit, which asks first. Screenshots (F12) of the steps are copied to OUT (for people to look at).
# Run by ctest as
#   with_xvfb.sh journey_new_player.sh PLATON OUT
set -eu
platon=$1
out=$2
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
settings="$data/config/platon/settings.txt"
mkdir -p "$out"
PLATON_PRINT_SCREEN=1 XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" game --record "$data/runs" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right k 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
# F12, then the screenshot kept as OUT/journey_NAME.png.
shot() {
  shots=$(grep -c "^screenshot: " "$log" || true)
  xdotool key F12
  await "^screenshot: " $((shots + 1))
  cp "$(grep "^screenshot: " "$log" | tail -1 | sed 's/^screenshot: //')" "$out/journey_$1.png" || fail "no screenshot for $1"
}
await_title
await "^screen> > 1\. .*par"
grep -q "^screen>   2\. .*(locked)" "$log" || fail "level 2 was open before level 1 was finished"
shot title
xdotool key Return
await "^playing cube_intro"
xdotool keydown Right
await "^level complete: cube_intro"
xdotool keyup Right
await "^screen> Level complete!"
shot complete
xdotool key Escape  # the title, level 2 chosen and open now
await "^screen> > 2\. [^(]*par [0-9]"
await "^screen>   1\. .*done "
xdotool key Tab  # the settings
await "^screen> Settings"
xdotool key Down Down Down Down Down Down Down Down Down Down Down  # the Jump row
await "^screen> > Jump  "
xdotool key Return
await "^screen> > Jump   press a key or pad button"
shot settings
xdotool key k
await "^settings: Jump is K$"
xdotool key Escape  # back to the title: saved
await "^settings: music"
grep -q "^keys_jump K$" "$settings" || fail "Jump is not K in the settings file: $(cat "$settings")"
xdotool key Return
await "^playing tetra_around"
xdotool keydown k
sleep 0.5
xdotool keyup k
xdotool keydown Right
sleep 1
xdotool keydown k
sleep 0.3
xdotool keyup k Right
shot playing
xdotool key Escape  # the pause menu
await "^screen> > Resume <"
xdotool key Down Down Down Down Return  # Quit
await "^quit asked"
await "^screen> Quit the game?"
shot quit_asked
xdotool key Return  # yes
await_exit "yes to the question did not end the game"
wait "$pid" || fail "the game failed"
replay=$(ls "$data"/runs/tetra_around*.replay 2>/dev/null | head -1)
[ -n "$replay" ] || fail "no recording of level 2: $(ls "$data/runs")"
grep -qE "^[0-9]+ .*jump" "$replay" || fail "K held no jump in level 2: $(cat "$replay")"
"$platon" replay "$replay" > "$data/replayed" 2>&1 || fail "level 2's recording differs: $(cat "$data/replayed")"
grep -q "^cube_intro " "$data/platon/progress.txt" || fail "the progress file does not record cube_intro"
echo "a new player's journey: title, level 1, level 2 open, Jump on K, level 2 jumped with K, quit asked"
rm -rf "$data"
