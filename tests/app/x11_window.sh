# Sourced by the window test drivers: finding and focusing `mobb view`'s window under xvfb-run.

# The window id once it is viewable (empty after 60 s).
find_window() {
  timeout 60 xdotool search --sync --onlyvisible --name "mobb view" | head -1 || true
}

# Waits (at most 60 s) for the window's title to name its scene, which it does once its first frames
# have placed the panels (src/viewer/window.cpp): a click before that lands elsewhere.
wait_placed() {
  timeout 60 xdotool search --sync --onlyvisible --name "mobb view - " >/dev/null || true
}

# Focus can fail with BadMatch while a loaded machine is still mapping the window: try again.
focus() {
  for _ in 1 2 3 4 5 6 7 8 9 10; do
    xdotool windowfocus "$1" 2>/dev/null && return 0
    sleep 0.5
  done
  xdotool windowfocus "$1"
}
