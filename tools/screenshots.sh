#!/usr/bin/env bash
# The README's pictures: one level on each solid and mesh stage, at a telling frame of its recorded
# play-through, rendered offscreen. usage: tools/screenshots.sh (after a build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
mkdir -p docs/screenshots
shot() {  # level replay frame
  build/apps/platon shot "$1" --input "tests/replays/$2.replay" --frame "$3" --size 640x360 --out "docs/screenshots/$1.png"
}
shot tetra_underside tetra_underside_drop 1010
shot cube_switches cube_switches_solve 300
shot octa_ring octa_ring_run 1000
shot dodeca_trapdoor dodeca_trapdoor_solve 230
shot icosa_drop icosa_drop_solve 640
shot prism prism_walk 500
shot soccer_ball soccer_ball_walk 500
# The title screen, with two levels done (a progress file of its own, not the user's).
data=$(mktemp -d)
mkdir -p "$data/platon"
printf 'cube_intro 1057 0\ntetra_around 988 1\n' > "$data/platon/progress.txt"
XDG_DATA_HOME="$data" SDL_VIDEODRIVER=${SDL_VIDEODRIVER:-offscreen} build/apps/platon game --first-frame-shot docs/screenshots/title.png > /dev/null
rm -rf "$data"
echo "docs/screenshots/title.png: the title screen"
# The editor (docs/editing.md): its window test on the cube, its pictures kept.
tests/tools/with_xvfb.sh tests/tools/real_window_editor.sh "$root/build/apps/platon" HEXAHEDRON "$root/docs/screenshots" > /dev/null
echo "docs/screenshots/editor_draw.png, editor_error.png, editor_play.png: the editor"
