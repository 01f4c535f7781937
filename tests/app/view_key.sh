#!/usr/bin/env bash
# Run inside xvfb-run: opens `mobb view SCENE` in a real window, holds KEY (an xdotool key name; none
# when empty) for 0.3 s once the window is up, and saves a screenshot at frame FRAMES.
# Usage: view_key.sh MOBB SCENE OUT FRAMES [KEY]
# (Keys are held rather than tapped: imgui 1.86 misses a press and release that arrive within one frame.)
set -euo pipefail
mobb=$1 scene=$2 out=$3 frames=$4 key=${5:-}
"$mobb" view "$scene" --frames "$frames" --screenshot "$out" --width 1280 --height 720 &
pid=$!
window=$(timeout 60 xdotool search --sync --name "mobb view" | head -1 || true)
sleep 0.5
if [ -n "$key" ]; then
  xdotool windowfocus "$window"
  xdotool mousemove --window "$window" 640 700
  xdotool keydown "$key"
  sleep 0.3
  xdotool keyup "$key"
fi
wait "$pid"
