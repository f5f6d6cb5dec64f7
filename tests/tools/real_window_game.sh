#!/bin/sh
# The game as a person plays it: a real window under Xvfb, keys typed with xdotool. Enter on the
# title screen starts the first level, hiding its window pauses it, holding Right walks it to the
# goal, Enter goes on to the next level, Esc and the pause menu quit. The level must be recorded as done in the progress file (a
# fresh XDG data folder), and the game must say where the player stood when it quit. Its sound goes
# to SDL's disk driver (what a sound card would play, as a file), which must not be silent. Run by
# ctest as
#   with_xvfb.sh real_window_game.sh PLATON
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE="$data/audio.raw" XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" game > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
await_title
xdotool key Return
await "^playing cube_intro"
# Another window takes the keyboard (here: the game's own is hidden a moment): the game pauses,
# and Esc in the pause menu goes on.
focus_window
xdotool windowunmap --sync "$window"
await "^paused: the window lost the focus"
xdotool windowmap --sync "$window"
focus_window
xdotool key Escape
xdotool keydown Right
await "^level complete: cube_intro"  # about 18 s of play; a slow machine drops steps
xdotool keyup Right
xdotool key Return
await "^playing tetra_around"
# The settings screen from the pause menu: music down to 40%, screen shake off, saved on the way
# back (a fresh XDG config folder).
xdotool key Escape Down Down Down Return Left Left Down Down Return Escape
await "^settings: music 40%, effects 90%, screen shake off"
grep -q "^music_volume 40" "$data/config/platon/settings.txt" || fail "the settings were not saved"
grep -q "^screen_shake off" "$data/config/platon/settings.txt" || fail "the settings were not saved"
xdotool key Escape  # the pause menu: resume
xdotool key Escape Down Down Down Down Return Return  # the pause menu: Quit, and yes
await_exit "Quit in the pause menu did not end the game"
wait "$pid" || fail "the game failed"
cat "$log"
grep -q "^cube_intro " "$data/platon/progress.txt" || fail "the progress file does not record cube_intro"
grep -q "^quit on tetra_around" "$log" || fail "the game did not say where it quit"
# The title's tune, the level's tune and its effects: samples far from silence, in most seconds.
loud=$(od -An -v -td2 -w4 "$data/audio.raw" | awk '{ n++; if ($1 > 2000 || $1 < -2000) l++ } END { printf "%d", 1000 * l / (n ? n : 1) }')
[ "$loud" -ge 20 ] || fail "the game was silent: $loud per mille of its samples are loud"
rm -rf "$data"
