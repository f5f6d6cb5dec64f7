#!/bin/sh
# Runs a command under a fresh Xvfb (xvfb-run -a), and once more if the X server did not start
# (another server starting at the same moment, another test or build, can take the display number
# xvfb-run picked) or started but refuses its clients: on a loaded machine xvfb-run's cookie can
# fail to be written (its xauth errors go nowhere), and every client is turned away; the game then
# found no display and, before it said so, ran without a window, and the test waited for one.
#   with_xvfb.sh COMMAND [ARGS...]
for attempt in 1 2 3; do
  out=$(mktemp)
  status=0
  xvfb-run -a -s "-screen 0 1280x720x24" sh -c '
    for _ in $(seq 50); do  # up to 5 s for the server to let a client in
      xdotool getmouselocation > /dev/null 2>&1 && exec "$@"
      sleep 0.1
    done
    echo "the X server refuses its clients"
    exit 75' with_xvfb "$@" > "$out" 2>&1 || status=$?
  if { grep -q "Xvfb failed to start" "$out" || grep -q "^the X server refuses its clients" "$out"; } &&
    [ "$attempt" -lt 3 ]; then
    echo "attempt $attempt: $(grep -m1 "Xvfb failed to start\|^the X server refuses" "$out"); again" >&2
    rm -f "$out"
    sleep 1
    continue
  fi
  cat "$out"
  rm -f "$out"
  exit "$status"
done
