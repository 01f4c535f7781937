#!/usr/bin/env bash
# The viewer's drawing speed (bench/results/render.md): `mobb render --bench` at 1280 x 720 on the
# 100-agent, 120 s crowd (all time and its +-5 s window), assets/scenes/bench.json and the default
# scene (also without multisampling and without its translucent layers), for each given build, the
# builds interleaved line by line, ROUNDS times (default 2). Prints fps, draw calls and vertices.
#   bench/render.sh RECORD.json MOBB_EXE [MOBB_EXE...]
# RECORD: mobb crowd --graph assets/graphs/cmu_locomotion.json --agents 100 --world 30x40 --seconds 120
#         --seed 11 --select wander --record RECORD.json
set -euo pipefail
cd "$(dirname "$0")/.."
record=$1
shift
rounds=${ROUNDS:-2}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The default scene without its translucent layers (cursor plane, box faces): their overdraw's cost.
python3 - "$tmp/opaque.json" <<'PY'
import json, sys
s = json.load(open("assets/scenes/default.json"))
s["layers"].update({"cursor": False, "box_faces": False})
json.dump(s, open(sys.argv[1], "w"))
PY
lines=(
  "crowd all time|--crowd $record --window 0 --bench-frames 10"
  "crowd window 5 s|--crowd $record --bench-frames 20"
  "bench scene|assets/scenes/bench.json --bench-frames 20"
  "default scene|assets/scenes/default.json --bench-frames 60"
  "default, --no-msaa|assets/scenes/default.json --no-msaa --bench-frames 60"
  "default, no translucent layers|$tmp/opaque.json --bench-frames 60"
  "default, --no-msaa, no translucent|$tmp/opaque.json --no-msaa --bench-frames 60"
)
echo "# $(date -u '+%Y-%m-%d %H:%M') UTC, load average $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 1; r <= rounds; ++r)); do
  for line in "${lines[@]}"; do
    name=${line%%|*}
    for exe in "$@"; do
      # shellcheck disable=SC2086
      out=$("$exe" render ${line#*|} --bench --width 1280 --height 720 2>&1) || out="failed: $out"
      echo "round $r | $name | $exe | $out"
    done
  done
done
echo "# done $(date -u '+%H:%M') UTC, load average $(cut -d' ' -f1-3 /proc/loadavg)"
