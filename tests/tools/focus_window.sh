# Sourced by the real-window tests: focus_window waits up to 10 s for the game's window and gives
# it the keyboard. A window can be found a moment before it can take the focus, or be one SDL
# replaces as it starts (X answers BadWindow), so finding and focusing are tried together until
# one works. Sets $window.
focus_window() {
  window=""
  for _ in $(seq 100); do
    for candidate in $(xdotool search --onlyvisible --name "Platon" 2>/dev/null); do
      if xdotool windowactivate --sync "$candidate" 2>/dev/null || xdotool windowfocus --sync "$candidate" 2>/dev/null; then
        window=$candidate
        return 0
      fi
    done
    sleep 0.1
  done
  return 1
}
