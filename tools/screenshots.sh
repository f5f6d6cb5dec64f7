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
