#!/usr/bin/env bash
# Run inside xvfb-run: opens `mobb view SCENE` in a real window once the display answers, holds KEY (an
# xdotool key name; none when empty) for 0.3 s once the window has placed its panels, then quits with Q;
# the screenshot is the last frame.
# Usage: view_key.sh MOBB SCENE OUT FRAMES [KEY]   (FRAMES: a cap, should Q never arrive)
# (Keys are held rather than tapped: imgui 1.86 misses a press and release that arrive within one frame.
# Quitting by key rather than after a frame count: llvmpipe draws 1280x720 at a few frames a second
# under load and far faster on an idle machine, so no count fits both.)
set -euo pipefail
# shellcheck source=x11_window.sh
source "$(dirname "$0")/x11_window.sh"
mobb=$1 scene=$2 out=$3 frames=$4 key=${5:-}
wait_display
"$mobb" view "$scene" --frames "$frames" --screenshot "$out" --width 1280 --height 720 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT  # no window left behind when a step fails
window=$(find_window "$pid")
wait_placed "$pid"
focus "$window"
xdotool mousemove --window "$window" 640 700
if [ -n "$key" ]; then
  xdotool keydown "$key"
  sleep 0.3
  xdotool keyup "$key"
fi
sleep 0.8  # a frame or more after the key
quit "$pid"
