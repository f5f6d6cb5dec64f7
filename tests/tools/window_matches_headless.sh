#!/bin/sh
# Plays a recorded run in a window (offscreen) and headless: the same state hash at the end, so
# the window changes nothing in the simulation. Also saves the window's last frame as a PNG.
#   window_matches_headless.sh PLATON REPLAY FRAMES OUT.png
set -eu
platon=$1 replay=$2 frames=$3 shot=$4
windowed=$(SDL_VIDEODRIVER=offscreen "$platon" play --input "$replay" --fast --frames "$frames" --shot "$shot" | tail -n 1)
headless=$("$platon" play --input "$replay" --fast --frames "$frames" --headless | tail -n 1)
echo "window:   $windowed"
echo "headless: $headless"
[ "$windowed" = "$headless" ] || { echo "the window changed the simulation"; exit 1; }
case "$windowed" in "state hash "*) ;; *) echo "no state hash printed"; exit 1 ;; esac
[ -s "$shot" ] || { echo "no screenshot at $shot"; exit 1; }
