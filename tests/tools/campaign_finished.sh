#!/usr/bin/env bash
# No level ships that nobody finished: every level of the campaign (levels/campaign.txt) checks
# clean, has a scenario in tests/scenarios that reaches its goal (ctest runs them all), and a
# recorded play-through in tests/replays that replays bit for bit here and finishes within the
# level's par time (a par nobody has met is a promise the game cannot keep).
# usage: campaign_finished.sh path/to/platon   (from the project root)
set -euo pipefail
platon="$1"
missing=0
while read -r folder par _; do
  [ -z "$folder" ] && continue
  scene="levels/$folder/scene.lua"
  scenarios=$(grep -l "scene = \"$scene\"" tests/scenarios/*.lua | xargs grep -l "goal_by" || true)
  replays=$(grep -l "^scene \"$scene\"" tests/replays/*.replay || true)
  if [ -z "$scenarios" ]; then echo "$folder: no scenario reaches its goal"; missing=1; continue; fi
  if [ -z "$replays" ]; then echo "$folder: no recorded play-through in tests/replays"; missing=1; continue; fi
  level=$(ls levels/"$folder"/*.level | head -1)
  "$platon" check "$level" > /dev/null || { echo "$folder: $level does not check clean"; missing=1; }
  # The scenario must finish the level (a scenario that only watches the player walk is not enough).
  for s in $scenarios; do
    "$platon" run --shard 1/1 "$s" > /tmp/campaign_finished.$$ 2>&1 || { cat /tmp/campaign_finished.$$; missing=1; }
    grep -q "goal at frame" /tmp/campaign_finished.$$ || { echo "$folder: $s does not reach the goal"; missing=1; }
  done
  [ -z "${par:-}" ] && { echo "$folder: no par time in levels/campaign.txt"; missing=1; continue; }
  par_frames=$(( (10#${par%%:*} * 60 + 10#${par##*:}) * 60 ))
  best=""
  for r in $replays; do
    "$platon" replay --shard 1/1 "$r" > /tmp/campaign_finished.$$ 2>&1 || { echo "$folder: $r does not replay"; missing=1; }
    goal=$(grep -o "goal at frame [0-9]*" /tmp/campaign_finished.$$ | grep -o "[0-9]*$" || true)
    [ -n "$goal" ] && { [ -z "$best" ] || [ "$goal" -lt "$best" ]; } && best=$goal
  done
  if [ -z "$best" ] || [ "$best" -gt "$par_frames" ]; then
    echo "$folder: no recorded play-through finishes within its par time $par ($par_frames frames; best: ${best:-none})"
    missing=1
  fi
  echo "$folder: finished by $(echo $scenarios | wc -w) scenario(s), $(echo $replays | wc -w) replay(s), in $best frames (par $par)"
done < <(sed 's/#.*//' levels/campaign.txt)
rm -f /tmp/campaign_finished.$$
exit $missing
