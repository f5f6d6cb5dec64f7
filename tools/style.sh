#!/usr/bin/env bash
# The repository's declared style, checked: every C and C++ file as .clang-format writes it, and the
# clang-tidy checks of .clang-tidy (bugprone, performance, function size) clean on the code that ships,
# and no function there over cyclomatic complexity 25 (tools/complexity.py).
#   tools/style.sh [BUILD_DIR]      (default build/: its compile_commands.json tells clang-tidy how
#                                    each file is compiled)
# `tools/style.sh --fix` rewrites the files clang-format would change instead of failing.
# Exits non-zero on the first kind of failure, naming the files.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
fix=0
[ "${1:-}" = "--fix" ] && { fix=1; shift; }
build="${1:-$root/build}"

# The project's C and C++ files: in a clone, the tracked ones and the new ones not yet added (a
# --fix before `git add` left four new files unformatted, and CI's style stage failed); every one
# under the source folders otherwise (an unpacked archive).
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.c' '*.cc' '*.cpp' '*.h' '*.hpp' | sort -u)
else
  mapfile -t files < <(find physics engine apps testing tests bench -name '*.c' -o -name '*.cc' -o -name '*.cpp' -o -name '*.h' -o -name '*.hpp' | sort)
fi

if ((fix)); then
  clang-format -i "${files[@]}"
  exit 0
fi

unformatted=()
for f in "${files[@]}"; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || unformatted+=("$f")
done
if ((${#unformatted[@]})); then
  echo "style: ${#unformatted[@]} of ${#files[@]} files differ from .clang-format (tools/style.sh --fix rewrites them):"
  printf '  %s\n' "${unformatted[@]}"
  exit 1
fi
echo "style: ${#files[@]} files as .clang-format writes them"

[ -f "$build/compile_commands.json" ] || { echo "style: no $build/compile_commands.json (configure first)"; exit 1; }
# The translation units of the code that ships, and the fixtures tests share (physics, engine, apps,
# testing; their headers are checked through them): the tests and benchmarks would double the time
# for code no player runs. -Wno-unknown-warning-option: GCC's flags that clang does not know.
mapfile -t units < <(printf '%s\n' "${files[@]}" | grep -E '^(physics|engine|apps|testing)/.*\.(c|cc|cpp)$' | sed "s|^|$root/|")
# A build/ made by tools/play compiles the engine as unity builds: its compile commands name no
# source file of ours, and clang-tidy would check nothing.
for unit in "${units[@]}"; do
  grep -qF "\"file\": \"$unit\"" "$build/compile_commands.json" && continue
  echo "style: $unit is not in $build/compile_commands.json (a unity build? configure with -DPLATON_UNITY=OFF)"
  exit 1
done
log="$(mktemp)"
if ! run-clang-tidy -p "$build" -quiet -j "$(nproc)" -extra-arg=-Wno-unknown-warning-option "${units[@]}" >"$log" 2>&1; then
  grep -E '(warning|error): ' "$log" | grep -v '^[0-9]* warnings' | sort -u | head -100
  echo "style: clang-tidy found the above ($(grep -cE '(warning|error): ' "$log") lines; full log: $log)"
  exit 1
fi
rm -f "$log"
echo "style: clang-tidy clean on ${#units[@]} files (.clang-tidy)"
# Cyclomatic complexity (if, loops, case, catch, ?:, && and ||, which clang-tidy's branch count
# leaves out) at most 25 in every function of the code that ships.
if ! "$root/tools/complexity.py" "$build" 25 "${units[@]}"; then
  echo "style: the functions above are over cyclomatic complexity 25: split them by what they do"
  exit 1
fi
