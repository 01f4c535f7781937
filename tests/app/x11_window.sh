# Sourced by the window test drivers under xvfb-run: waiting for the display and for `mobb view`'s window
# by asking the X server (never a fixed sleep), focusing it, and quitting it. Each wait gives up after 60 s.
# The tests start Xvfb with -noreset: an X server resets when its last client leaves and refuses the clients
# that connect meanwhile ("Can't open display", GLFW "Failed to open display"), as mobb view would after
# wait_display's xdotool left, or xdotool after a client of mobb view's left.

# Waits until the X server on $DISPLAY answers.
wait_display() {
  local deadline=$((SECONDS + 60))
  until xdotool getdisplaygeometry >/dev/null 2>&1; do
    if [ $SECONDS -ge $deadline ]; then
      echo "the X server on DISPLAY=${DISPLAY:-(unset)} did not answer in 60 s" >&2
      return 1
    fi
    sleep 0.1
  done
}

# Prints the id of the first viewable window whose title holds NAME once it shows; fails when process PID
# ends first.
window_named() {
  local name=$1 pid=$2 deadline=$((SECONDS + 60)) id
  while :; do
    id=$(xdotool search --onlyvisible --name "$name" 2>/dev/null | head -1 || true)
    if [ -n "$id" ]; then
      echo "$id"
      return 0
    fi
    if ! kill -0 "$pid" 2>/dev/null; then
      echo "mobb view ended before a window titled '$name' showed" >&2
      return 1
    fi
    if [ $SECONDS -ge $deadline ]; then
      echo "no window titled '$name' in 60 s" >&2
      return 1
    fi
    sleep 0.1
  done
}

# The window of `mobb view` (process PID) once it is viewable.
find_window() { window_named "mobb view" "$1"; }

# Waits for the window's title to name its scene, which it does once its first frames have placed the
# panels (src/viewer/window.cpp): a click before that lands elsewhere.
wait_placed() { window_named "mobb view - " "$1" >/dev/null; }

# Focus can fail with BadMatch while a loaded machine is still mapping the window: try again.
focus() {
  for _ in 1 2 3 4 5 6 7 8 9 10; do
    xdotool windowfocus "$1" 2>/dev/null && return 0
    sleep 0.5
  done
  xdotool windowfocus "$1"
}

# Quits `mobb view` (process PID) with Q, held 0.15 s (imgui 1.86 misses a press and release within one
# frame), and waits for it to end; Q again every 2 s while it runs, as a loaded machine may draw no frame
# while Q is held. Returns the process's exit status (non-zero when it had to be killed).
quit() {
  local pid=$1 deadline=$((SECONDS + 60))
  while kill -0 "$pid" 2>/dev/null && [ $SECONDS -lt $deadline ]; do
    xdotool keydown q
    sleep 0.15
    xdotool keyup q
    for _ in $(seq 20); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "mobb view still ran 60 s after the first Q" >&2
    kill "$pid"
  fi
  wait "$pid"
}
