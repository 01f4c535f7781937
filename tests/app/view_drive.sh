#!/usr/bin/env bash
# Run inside xvfb-run: opens `mobb view SCENE` in a real 1280x720 window once the display answers, sends
# real input events (xdotool) once the window has placed its panels, then quits with Q; the window saves a
# screenshot and the scene as it was left.
# Usage: view_drive.sh MOBB SCENE OUT.png STATE.json [ACTION...]
# Actions: key:NAME (an xdotool key name, held 0.15 s: imgui 1.86 misses a press and release within one
# frame, and 0.15 s is under its repeat delay), click:X:Y (window pixels), type:TEXT, wait:SECONDS.
set -euo pipefail
# shellcheck source=x11_window.sh
source "$(dirname "$0")/x11_window.sh"
mobb=$1 scene=$2 out=$3 state=$4
shift 4
wait_display
"$mobb" view "$scene" --frames 100000 --screenshot "$out" --save-state "$state" --width 1280 --height 720 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT  # no window left behind when a step fails
window=$(find_window "$pid")
wait_placed "$pid"
focus "$window"
xdotool mousemove --window "$window" 640 700
for action in "$@"; do
  case $action in
    key:*) xdotool keydown "${action#key:}"; sleep 0.15; xdotool keyup "${action#key:}" ;;
    click:*) IFS=: read -r _ x y <<<"$action"
             xdotool mousemove --window "$window" "$x" "$y"; sleep 0.2
             xdotool mousedown 1; sleep 0.4; xdotool mouseup 1 ;;  # a frame or more down, under load
    type:*) xdotool type --delay 80 "${action#type:}" ;;
    wait:*) sleep "${action#wait:}" ;;
    *) echo "unknown action $action" >&2; kill "$pid"; exit 2 ;;
  esac
  sleep 0.8  # a frame or more: llvmpipe under load draws a few frames a second
done
xdotool mousemove --window "$window" 640 700
quit "$pid"
