#!/usr/bin/env bash
# Measures what a newcomer waits for: from a fresh clone on a fresh Debian bookworm system to the
# game's title screen, package installation included (tools/play). The fresh system is a minimal
# debootstrap chroot (--variant=minbase: not even a compiler or cmake, so it is harsher than a
# fresh machine), made once into BASE and copied for each run, so every run starts clean.
#   tools/first_run.sh BASE [RUNS]      (root; BASE is made with debootstrap when it does not exist)
# Prints each run's seconds to the first frame of the title screen (rendered offscreen, saved as
# a PNG, then the game quits: `tools/play --first-frame-shot`) and the median.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
base="$1"
runs="${2:-1}"
command -v bc >/dev/null || apt-get install -y -qq bc >/dev/null
if [ ! -d "$base/usr" ]; then
  command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap >/dev/null
  debootstrap --variant=minbase bookworm "$base" http://deb.debian.org/debian >/dev/null
fi
cp /etc/apt/sources.list.d/debian.sources "$base/etc/apt/sources.list.d/" 2>/dev/null || true
times=()
for run in $(seq "$runs"); do
  fresh="$base.run$run"
  rm -rf "$fresh"
  cp -a "$base" "$fresh"
  git clone -q "$root" "$fresh/root/platon"  # what was committed, as a clone has it
  mount -t proc proc "$fresh/proc"
  mount --bind /dev "$fresh/dev"
  trap 'umount "$fresh/proc" "$fresh/dev" 2>/dev/null' EXIT
  start=$(date +%s.%N)
  status=0
  chroot "$fresh" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root SDL_VIDEODRIVER=offscreen \
    /bin/bash -c 'cd /root/platon && tools/play --first-frame-shot /root/title.png' >"$fresh.log" 2>&1 || status=$?
  end=$(date +%s.%N)
  umount "$fresh/proc" "$fresh/dev"
  seconds=$(echo "$end - $start" | bc)
  if ((status != 0)) || [ ! -s "$fresh/root/title.png" ]; then
    tail -n 30 "$fresh.log"
    echo "run $run: failed after $seconds s (log: $fresh.log)"
    exit 1
  fi
  cp "$fresh/root/title.png" "$base.title.png"
  echo "run $run: $seconds s from the clone to the title screen"
  times+=("$seconds")
  rm -rf "$fresh"
done
printf '%s\n' "${times[@]}" | sort -n | awk '{a[NR]=$1} END {printf "median %.0f s (min %.0f, max %.0f) of %d runs\n", a[int((NR+1)/2)], a[1], a[NR], NR}'
