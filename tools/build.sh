#!/usr/bin/env bash
# Configures (Release) and builds into build/, using every core.
#   tools/build.sh --game   only the game: its packages (tools/deps.sh game), the program and its
#                           plugins. A new build/ is configured without tests and benchmarks, its
#                           game targets as unity builds (half the compiler's work); a build/
#                           configured before keeps its options.
#   tools/build.sh [cmake options]   everything (tools/deps.sh all), tests and benchmarks on
# A new build folder uses Ninja (it compiles the modules side by side where make waits for each
# library in turn).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
# A build/ made where the checkout was before it moved names the old folder: start it again.
cache="$root/build/CMakeCache.txt"
if [ -f "$cache" ] && ! grep -qx "CMAKE_HOME_DIRECTORY:INTERNAL=$root" "$cache"; then
  echo "build/ was configured for another folder: configuring it again"
  rm -rf "$cache" "$root/build/CMakeFiles"
fi
fresh=()
[ -f "$cache" ] || fresh=(-G Ninja)
if [ "${1:-}" = "--game" ]; then
  "$root/tools/deps.sh" game
  ((${#fresh[@]})) && fresh+=(-DPLATON_BUILD_TESTS=OFF -DPLATON_BUILD_BENCH=OFF -DPLATON_UNITY=ON)
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "${fresh[@]}" >/dev/null
  cmake --build "$root/build" -j"$(nproc)" --target platon platon_render_plugin platon_mesh_plugin
  exit 0
fi
"$root/tools/deps.sh" all
# The engine's sources one by one: tools/style.sh gives clang-tidy their compile commands.
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DPLATON_BUILD_TESTS=ON -DPLATON_BUILD_BENCH=ON \
  -DPLATON_UNITY=OFF "${fresh[@]}" "$@" >/dev/null
cmake --build "$root/build" -j"$(nproc)"
