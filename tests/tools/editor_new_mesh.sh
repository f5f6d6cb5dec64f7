#!/bin/sh
# `platon edit --new MESH-FILE FOLDER` on a mesh (offscreen GL): the folder holds the mesh, a scene
# that names the meshes system and a level on it with a face line for each of the mesh's faces and
# the start and goal on its face 0, which `platon check` accepts and the editor opens again; a file
# that is no mesh is refused and leaves no folder behind. Run by ctest as
#   editor_new_mesh.sh PLATON
set -eu
platon=$(realpath "$1")
export SDL_VIDEODRIVER=offscreen
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
"$platon" edit --new levels/prism/prism.ply "$data/onprism" --shot "$data/first.png"
[ -s "$data/first.png" ] || { echo "no picture"; exit 1; }
[ -f "$data/onprism/prism.ply" ] || { echo "the mesh was not copied in"; exit 1; }
grep -q '"meshes"' "$data/onprism/scene.lua" || { echo "the scene does not name the meshes system"; exit 1; }
grep -q '^MESH prism.ply$' "$data/onprism/onprism.level" || { echo "the level is not on the mesh"; exit 1; }
"$platon" check "$data/onprism" || { echo "platon check refuses the new level"; exit 1; }
"$platon" edit "$data/onprism" --shot "$data/again.png" | grep -q "^editing " || { echo "it does not open again"; exit 1; }
# A mesh file that is none: refused, and nothing left behind.
printf 'not a mesh\n' > "$data/bad.ply"
if "$platon" edit --new "$data/bad.ply" "$data/onbad" --shot "$data/bad.png" 2> "$data/err"; then echo "a bad mesh was taken"; exit 1; fi
[ ! -e "$data/onbad" ] || { echo "a half-made level was left behind"; exit 1; }
echo "a new level on a mesh: made and opened"
