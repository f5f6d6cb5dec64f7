#!/usr/bin/env bash
# Installs the Debian packages that are missing (root on a fresh machine; sudo otherwise).
#   tools/deps.sh game   what building and playing the game needs (tools/play)
#   tools/deps.sh all    that, and what the tests, checks, benchmarks and fuzzers need (tools/test)
set -euo pipefail
group="${1:-all}"
game=(cmake ninja-build make g++ pkg-config
  libluajit-5.1-dev  # the script module (LuaJIT 2.1)
  libeigen3-dev      # the stage and camera modules (header-only)
  libassimp-dev      # the meshes plugin: OBJ, glTF, PLY, STL stages
  libtinyxml2-dev    # platon run's and merge's JUnit reports
  # the renderer plugin: SDL2 window, GL loader, text, PNG screenshots, the font; Mesa for GL
  # without a GPU (SDL_VIDEODRIVER=offscreen: tools/play's picture when there is no display)
  libsdl2-dev libsdl2-ttf-dev libsdl2-image-dev libepoxy-dev fonts-dejavu-core libgl1-mesa-dri libegl1
  libsdl2-mixer-dev  # the audio plugin (its sounds are synthesized: no sound files)
  libarchive-dev nettle-dev)  # level packages (.platon): tar and gzip, SHA-256
checks=(libgtest-dev libgmock-dev libbenchmark-dev
  libbox2d-dev libchipmunk-dev        # the peers of the benchmarks
  clang libclang-rt-14-dev            # the fuzz stage: libFuzzer and the sanitizer runtimes
  clang-format clang-tidy             # tools/style.sh
  python3-clang-14                    # tools/complexity.py: clang's own parse, for the complexity limit
  lua-check                           # luacheck: the Lua lint (.luacheckrc)
  xvfb xauth xdotool                  # the real-window tests
  dpkg-dev desktop-file-utils appstream  # the package stage: cpack's dpkg-shlibdeps, the desktop entry and AppStream checks
  util-linux)                         # unshare: the installed package is tested with the sources out of reach
case "$group" in
  game) packages=("${game[@]}") ;;
  all) packages=("${game[@]}" "${checks[@]}") ;;
  *) echo "usage: tools/deps.sh game|all" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
