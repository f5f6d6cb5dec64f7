#!/usr/bin/env bash
# Installs the Debian packages the build needs, only if some are missing (root on a fresh machine).
set -euo pipefail
# clang + libclang-rt-14-dev (the libFuzzer and sanitizer runtimes): the fuzz stage of tools/test.
packages=(cmake make g++ pkg-config libgtest-dev libgmock-dev libbenchmark-dev libbox2d-dev libchipmunk-dev
  clang libclang-rt-14-dev
  libluajit-5.1-dev  # the script module (LuaJIT 2.1)
  libeigen3-dev      # the stage module: solids, face frames (header-only)
  libassimp-dev      # the meshes plugin: OBJ, glTF, PLY, STL stages
  # the renderer plugin: SDL2 window, GL loader, text, PNG screenshots, the font; Mesa for GL
  # without a GPU (SDL_VIDEODRIVER=offscreen), Xvfb and xdotool for the real-window test
  libsdl2-dev libsdl2-ttf-dev libsdl2-image-dev libepoxy-dev fonts-dejavu-core
  libgl1-mesa-dri libegl1 xvfb xauth xdotool)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
