#!/usr/bin/env bash
# Levels that travel (docs/packages.md), as a player meets them: a level packed with the run that
# finishes it, installed into the player's levels folder and listed on the title screen; and the
# packages install must refuse though every hash in them is right (made here by hand with tar and
# sha256sum, as anyone could): a run that does not reach the goal, a level with an error. A refused
# package leaves nothing behind, not even its staging folder.
# usage: pack_install.sh path/to/platon   (from the project root)
set -euo pipefail
platon="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_DATA_HOME="$work/data" XDG_CONFIG_HOME="$work/config"
levels="$XDG_DATA_HOME/platon/levels"
fail() { echo "FAIL: $*"; exit 1; }

"$platon" pack levels/cube_intro --replay tests/replays/cube_intro_walk.replay -o "$work/intro.platon"
"$platon" install "$work/intro.platon"
[ -f "$levels/cube_intro/scene.lua" ] || fail "not installed"
[ -f "$levels/cube_intro/finish.replay" ] || fail "its run was not installed"
"$platon" replay "$levels/cube_intro/finish.replay" > /dev/null || fail "the installed run does not replay"
if "$platon" install "$work/intro.platon" 2> "$work/again.txt"; then fail "installed twice"; fi
grep -q "is installed (remove it first)" "$work/again.txt" || fail "a second install: $(cat "$work/again.txt")"
out=$(SDL_VIDEODRIVER=offscreen "$platon" game --first-frame-shot "$work/title.png" 2>&1)
campaign=$(sed 's/#.*//' levels/campaign.txt | grep -c '[^[:space:]]')  # the campaign, and the one installed
echo "$out" | grep -q "title screen: $((campaign + 1)) levels" || fail "the title screen does not list it: $out"

# A package with every hash right, of the folder $1 under $work/src.
package() {
  local folder="$1" out="$2" files=() lines="" entries=""
  cd "$work/src"
  while IFS= read -r f; do files+=("$f"); done < <(cd "$folder" && find . -type f | sed 's|^\./||' | LC_ALL=C sort)
  for f in "${files[@]}"; do
    local bytes sha
    bytes=$(stat -c %s "$folder/$f")
    sha=$(sha256sum "$folder/$f" | cut -d' ' -f1)
    lines+="$f"$'\t'"$bytes"$'\t'"$sha"$'\n'
    entries+="    { path = \"$f\", bytes = $bytes, sha256 = \"$sha\" },"$'\n'
  done
  local hash
  hash=$(printf '%s' "$lines" | while IFS=$'\t' read -r p b s; do printf '%s\0%s\0%s\n' "$p" "$b" "$s"; done | sha256sum | cut -d' ' -f1)
  printf 'return {\n  format = 1,\n  name = "%s",\n  folder = "%s",\n  hash = "%s",\n  files = {\n%s  },\n}\n' \
    "$folder" "$folder" "$hash" "$entries" > package.lua
  tar czf "$out" package.lua $(for f in "${files[@]}"; do echo "$folder/$f"; done)
  rm package.lua
  cd - > /dev/null
}

refused() {  # refused PACKAGE WHY
  if "$platon" install "$1" 2> "$work/why.txt"; then fail "$1 installed"; fi
  grep -q "$2" "$work/why.txt" || fail "$1: $(cat "$work/why.txt")"
  [ -z "$(ls -A "$levels" | grep -v '^cube_intro$' || true)" ] || fail "$1 left $(ls -A "$levels")"
}

# A run that stops short of the goal: input only, 300 frames of walking.
mkdir -p "$work/src/shortrun"
cp levels/cube_intro/* "$work/src/shortrun/"
printf 'platon replay 1\nscene "scene.lua"\nframes 300\nhash_every 60\ninput\n300 right\nend\n' > "$work/src/shortrun/finish.replay"
package shortrun "$work/short.platon"
refused "$work/short.platon" "does not finish the level: goal not reached"

# A level with an error: its start inside the floor.
mkdir -p "$work/src/badlevel"
cp levels/cube_intro/* "$work/src/badlevel/"
sed -i 's/^0 600 700 /0 600 512 /' "$work/src/badlevel/cube_intro.level"
cp tests/replays/cube_intro_walk.replay "$work/src/badlevel/finish.replay"
sed -i 's|^scene .*|scene "scene.lua"|' "$work/src/badlevel/finish.replay"
package badlevel "$work/bad.platon"
refused "$work/bad.platon" "the level has errors"

# A package carries data and the Lua its scene loads, nothing else: a kept test (Lua a person might
# run), a script nothing loads, a program. pack leaves them out and says so; a package made by hand
# that carries them installs without them, and install names each one it refused.
mkdir -p "$work/src/extras/sub"
cp levels/cube_intro/* "$work/src/extras/"
printf 'os.execute("touch %s/ran")\nreturn {}\n' "$work" > "$work/src/extras/test_1.lua"
printf '#!/bin/sh\ntouch %s/ran\n' "$work" > "$work/src/extras/sub/run.sh"
printf 'return {}\n' > "$work/src/extras/unused.lua"
printf 'A level of mine.\n' > "$work/src/extras/README.md"
"$platon" pack "$work/src/extras" --replay tests/replays/cube_intro_walk.replay -o "$work/extras.platon" > "$work/pack.txt"
for f in "sub/run.sh: not a kind a level is made of" "test_1.lua: Lua that scene.lua does not load" "unused.lua: Lua"; do
  grep -q "left out $f" "$work/pack.txt" || fail "pack did not say it left out $f: $(cat "$work/pack.txt")"
done
listed=$(tar tzf "$work/extras.platon")
for f in test_1.lua sub/run.sh unused.lua; do
  if echo "$listed" | grep -q "extras/$f"; then fail "pack carried $f"; fi
done
echo "$listed" | grep -q "extras/README.md" || fail "pack left out the read-me: $listed"
echo "$listed" | grep -q "extras/level.lua" || fail "pack left out the level's script: $listed"
cp tests/replays/cube_intro_walk.replay "$work/src/extras/finish.replay"
sed -i 's|^scene .*|scene "scene.lua"|' "$work/src/extras/finish.replay"
package extras "$work/extras_by_hand.platon"
"$platon" install "$work/extras_by_hand.platon" > "$work/install.txt" || fail "the package with extras was refused"
for f in "refused sub/run.sh" "refused test_1.lua" "refused unused.lua"; do
  grep -q "$f" "$work/install.txt" || fail "install did not say $f: $(cat "$work/install.txt")"
done
for f in test_1.lua sub/run.sh unused.lua; do
  [ ! -e "$levels/extras/$f" ] || fail "install put $f in the player's levels"
done
[ -f "$levels/extras/level.lua" ] && [ -f "$levels/extras/README.md" ] || fail "install lost the level's own files"
[ ! -e "$work/ran" ] || fail "something the package carried ran"
rm -rf "$levels/extras"

# The good one, made by hand the same way, installs: the tool above is how a package is made.
mkdir -p "$work/src/handmade"
cp levels/cube_intro/* "$work/src/handmade/"
cp "$levels/cube_intro/finish.replay" "$work/src/handmade/finish.replay"
package handmade "$work/handmade.platon"
"$platon" install "$work/handmade.platon" > /dev/null || fail "a right package made by hand was refused"
echo "pack and install: ok"
