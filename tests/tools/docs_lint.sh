#!/bin/sh
# Every Lua example in the docs (docs/*.md, README.md) passes the lint the docs recommend (.luacheckrc: the
# sandbox's globals for what runs sandboxed: levels, mods, players, rules), as a modder who copies
# one would lint it. Replays and signature lists are not Lua. Run by ctest from the source tree as
#   docs_lint.sh
set -eu
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/levels"
cp .luacheckrc "$work/"
for doc in docs/*.md README.md; do
  awk -v out="$work/levels" -v doc="$(basename "$doc" .md)" '
    !inside && /^```lua/ { inside = 1; kind = substr($0, 8); file = out "/" doc "_line_" FNR "_" kind ".lua"; next }
    inside && /^```$/ { inside = 0; if (kind == "replay" || kind == "signatures") system("rm -f \"" file "\""); next }
    inside { print > file }
  ' "$doc"
done
count=$(ls "$work/levels" | wc -l)
[ "$count" -ge 10 ] || { echo "only $count Lua examples found in the docs"; exit 1; }
cd "$work" && luacheck --no-color --codes levels
echo "the $count Lua examples of the docs pass the lint"
