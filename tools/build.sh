#!/usr/bin/env bash
# Configures (Release) and builds into build/, using every core.
#   tools/build.sh --game   only the game: its packages (tools/deps.sh game), the program and its
#                           plugins; a build/ configured before keeps its options, a new one is
#                           configured without tests and benchmarks
#   tools/build.sh [cmake options]   everything (tools/deps.sh all), tests and benchmarks on
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
if [ "${1:-}" = "--game" ]; then
  "$root/tools/deps.sh" game
  options=()
  [ -f "$root/build/CMakeCache.txt" ] || options=(-DPLATON_BUILD_TESTS=OFF -DPLATON_BUILD_BENCH=OFF)
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "${options[@]}" >/dev/null
  cmake --build "$root/build" -j"$(nproc)" --target platon platon_render_plugin platon_mesh_plugin
  exit 0
fi
"$root/tools/deps.sh" all
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DPLATON_BUILD_TESTS=ON -DPLATON_BUILD_BENCH=ON "$@" >/dev/null
cmake --build "$root/build" -j"$(nproc)"
