#!/bin/sh
# tools/complexity.py (tools/style.sh's cyclomatic limit) counts every kind of decision, the
# lambdas' in their holder's, and fails on exactly the functions over its limit. Run by ctest from
# the source tree as
#   complexity_test.sh BUILD_DIR
set -u
build="$1"
fixture=tests/tools/complexity/fixture.cpp
out=$(tools/complexity.py "$build" 25 "$fixture" 2>/dev/null)
status=$?
[ "$status" -eq 1 ] || { echo "limit 25: exit $status, expected 1 (a function is over it)"; exit 1; }
[ "$out" = "$fixture:43: over26 complexity 26 (limit 25)" ] || { echo "limit 25 reported:"; echo "$out"; exit 1; }
tools/complexity.py "$build" 26 "$fixture" >/dev/null 2>&1 || { echo "limit 26: a function was reported over it"; exit 1; }
all=$(tools/complexity.py "$build" 0 "$fixture" 2>/dev/null)
for want in "at25 complexity 25" "over26 complexity 26" "plain complexity 1"; do
  echo "$all" | grep -q "$want" || { echo "limit 0: no '$want' in:"; echo "$all"; exit 1; }
done
echo "complexity: at25 25, over26 26 (the one over 25), plain 1"
