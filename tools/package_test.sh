#!/usr/bin/env bash
# The game as a user installs it: the Debian package that cpack makes from BUILD_DIR (build/),
# unpacked into a scratch root, checked (desktop entry, AppStream data, no path of this machine
# in the program), and the shipped scenarios and replays run by the installed program from there,
# with the source tree out of reach (an empty folder mounted over it, where unshare can; the
# tree is then not readable even by mistake), from another folder, with a bare environment.
#   tools/package_test.sh [BUILD_DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
fail() { echo "package: $*"; exit 1; }

(cd "$build" && rm -f platon_*.deb && cpack -G DEB >/dev/null) || fail "cpack could not make the package"
deb=$(ls "$build"/platon_*.deb)
scratch=$(mktemp -d /tmp/platon-installed-XXXXXX)
trap 'rm -rf "$scratch"' EXIT
dpkg-deb -x "$deb" "$scratch"
usr="$scratch/usr"
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB, unpacked into $scratch"
dpkg-deb -f "$deb" Depends

desktop-file-validate "$usr"/share/applications/*.desktop || fail "the desktop entry does not validate"
appstreamcli validate --no-net "$usr"/share/metainfo/*.metainfo.xml || fail "the AppStream data does not validate"
[ -s "$usr/share/icons/hicolor/scalable/apps/io.github.platon_game.Platon.svg" ] || fail "no icon"
for f in "$usr/bin/platon" "$usr"/lib/platon/*.so; do
  ! grep -q -F "$root" "$f" || fail "$f names the source tree ($root)"
done

scenarios=("$usr"/share/platon/scenarios/*.lua)
replays=("$usr"/share/platon/replays/*.replay)
((${#scenarios[@]} > 0 && ${#replays[@]} > 0)) || fail "no shipped scenarios or replays"
# What runs installed: every shipped scenario and replay, a level's picture through the renderer
# plugin (offscreen GL), and the game's title screen (the campaign found in the data folder). Run from the scratch root with nothing of this shell's environment.
script=$(cat <<SH
set -e
cd "$scratch"
env -i PATH=/usr/bin:/bin HOME="$scratch" "$usr/bin/platon" run --shard 1/1 -j $(nproc) ${scenarios[*]} ${replays[*]}
env -i PATH=/usr/bin:/bin HOME="$scratch" SDL_VIDEODRIVER=offscreen "$usr/bin/platon" shot cube_intro --frame 60 --out "$scratch/shot.png"
env -i PATH=/usr/bin:/bin HOME="$scratch" SDL_VIDEODRIVER=offscreen "$usr/bin/platon" game --first-frame-shot "$scratch/title.png"
SH
)
if unshare --mount --fork true 2>/dev/null; then
  echo "package: the source tree $root is hidden (an empty tmpfs over it)"
  unshare --mount --fork sh -c "mount -t tmpfs -o ro none '$root' && $script" || fail "the installed game failed (above)"
else
  echo "package: unshare is not allowed here: the source tree stays, but nothing installed names it (checked above)"
  sh -c "$script" || fail "the installed game failed (above)"
fi
[ -s "$scratch/shot.png" ] && [ -s "$scratch/title.png" ] || fail "no picture from the installed renderer"
echo "package: ${#scenarios[@]} scenarios and ${#replays[@]} replays pass, installed, with no source tree"
