#!/bin/sh
# Every workload, one `mobb bench` run each, then (for the query workloads) callgrind instruction counts
# merged in:
#   bench/run_all.sh BUILD_DIR [WORKLOAD...]      (default: table1 table2 synth42 synth120 scale crowd)
# Writes bench/results/WORKLOAD.{md,json,png}; each .md ends with the load averages before and after
# its run (the machine is shared) and, for the query workloads, instructions per query.
# BUILD_DIR: a Release build with mobb and mobb_query_driver (needs the CMU data and valgrind).
set -eu
build=${1:?usage: bench/run_all.sh BUILD_DIR [WORKLOAD...]}
shift
root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/bench/results"
mobb="$build/src/app/mobb"
workloads=${*:-table1 table2 synth42 synth120 scale crowd}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for w in $workloads; do
  echo "== $w ($(date -u +%H:%M:%S) UTC)" >&2
  before=$(cut -d' ' -f1-3 /proc/loadavg)
  start=$(date +%s)
  case $w in
    scale) "$mobb" bench scale --quiet --json "$out/$w.json" --png "$out/$w.png" --save-queries "$tmp/$w.queries" > "$out/$w.md" ;;
    crowd) "$mobb" bench crowd --quiet --json "$out/$w.json" --png "$out/$w.png" > "$out/$w.md" ;;
    *) "$mobb" bench "$w" --quiet --json "$out/$w.json" --png "$out/$w.png" --save-queries "$tmp/$w.queries" > "$out/$w.md" ;;
  esac
  after=$(cut -d' ' -f1-3 /proc/loadavg)
  printf -- '- run: `mobb bench %s`, %s s wall, %s UTC; load average (1, 5, 15 min) before %s, after %s on %s cores (shared machine)\n' \
    "$w" "$(($(date +%s) - start))" "$(date -u '+%Y-%m-%d %H:%M')" "$before" "$after" "$(nproc)" >> "$out/$w.md"
  [ "$w" = crowd ] || "$root/bench/callgrind_workload.sh" "$w" "$build" "$tmp/$w.queries"
done
