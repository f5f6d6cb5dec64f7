# Sourced by the real-window tests (Xvfb, keys typed with xdotool). Every wait is for something the
# game says or does, never a fixed time: a loaded machine, or an ASan build, is slow, not wrong (and
# the game drops steps when it cannot keep up, so 18 s of play may take minutes). A wait gives up
# after $PLATON_WINDOW_WAIT seconds (300), which only a broken game reaches.
# The test sets $log (the game's output) and $pid, and defines fail MESSAGE.
wait_limit=$(( ${PLATON_WINDOW_WAIT:-300} * 10 ))  # in tenths of a second

# Waits for the game's window and gives it the keyboard. A window can be found a moment before it
# can take the focus, or be one SDL replaces as it starts (X answers BadWindow), so finding and
# focusing are tried together until one works. Sets $window.
focus_window() {
  window=""
  for _ in $(seq "$wait_limit"); do
    for candidate in $(xdotool search --onlyvisible --name "Platon" 2>/dev/null); do
      if xdotool windowactivate --sync "$candidate" 2>/dev/null || xdotool windowfocus --sync "$candidate" 2>/dev/null; then
        window=$candidate
        return 0
      fi
    done
    kill -0 "$pid" 2>/dev/null || fail "the game ended before its window appeared"
    sleep 0.1
  done
  fail "no window appeared that could take the keyboard; the X server's windows: $(windows_seen)"
}

# What the X server shows, for a failure's message: every window with a name, visible or not, and
# (when xwininfo is there) whether it is mapped.
windows_seen() {
  for w in $(xdotool search --name "." 2>/dev/null); do
    state=$(command -v xwininfo > /dev/null && xwininfo -id "$w" 2>/dev/null | sed -n 's/.*Map State: //p')
    echo "[$w '$(xdotool getwindowname "$w" 2>/dev/null)' ${state:-?}]"
  done | tr '\n' ' '
  echo "(DISPLAY=$DISPLAY)"
}

# Waits for a line of the log matching $1; $2 (optional) says how many such lines are wanted.
await() {
  for _ in $(seq "$wait_limit"); do
    [ "$(grep -c -- "$1" "$log" || true)" -ge "${2:-1}" ] && return 0
    kill -0 "$pid" 2>/dev/null || fail "the game ended before a line '$1'"
    sleep 0.1
  done
  fail "no line '$1' in the log"
}

# Waits for the game to end by itself; fails if it goes on.
await_exit() {
  for _ in $(seq "$wait_limit"); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  fail "$1"
}

# The game's window, focused, once its title screen is shown (it reads keys from then on).
await_title() {
  focus_window
  await "^title screen"
}
