#!/bin/sh
# Runs a command under a fresh Xvfb (xvfb-run -a), and once more if the X server did not start:
# another server starting at the same moment (another test, another build) can take the display
# number xvfb-run picked.
#   with_xvfb.sh COMMAND [ARGS...]
for attempt in 1 2 3; do
  out=$(mktemp)
  status=0
  xvfb-run -a -s "-screen 0 1280x720x24" "$@" > "$out" 2>&1 || status=$?
  if grep -q "Xvfb failed to start" "$out" && [ "$attempt" -lt 3 ]; then
    echo "attempt $attempt: the X server did not start; again" >&2
    rm -f "$out"
    sleep 1
    continue
  fi
  cat "$out"
  rm -f "$out"
  exit "$status"
done
