#!/bin/sh
# `platon defs DIR --for LEVEL`: the language server's settings point at the definitions by a path
# from their own folder, never by this machine's (a .luarc.json travels with the level), and the
# path reaches them. Run by ctest as
#   defs_paths.sh PLATON
set -eu
platon=$1
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
mkdir -p "$data/levels/mine"
(cd "$data" && "$platon" defs defs --for levels/mine) > "$data/log" 2>&1 || { cat "$data/log"; exit 1; }
for f in "$data/defs/sandbox/.luarc.json" "$data/defs/trusted/.luarc.json" "$data/levels/mine/.luarc.json"; do
  if grep -q '"/' "$f"; then echo "an absolute path in $f:"; cat "$f"; exit 1; fi
done
library=$(sed -n 's/.*"workspace.library": \["\([^"]*\)"\].*/\1/p' "$data/levels/mine/.luarc.json")
[ -f "$data/levels/mine/$library/platon.lua" ] || { echo "the level's settings point at nothing: $library"; exit 1; }
grep -q '"io": "disable"' "$data/levels/mine/.luarc.json" || { echo "a level's scripts are sandboxed: io off"; exit 1; }
echo "relative: $library"
