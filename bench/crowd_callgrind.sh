#!/bin/sh
# Instructions per query (callgrind) of fast, scan, mobb1 and mobb on issue 5's workloads.
# Usage: bench/crowd_callgrind.sh BUILD_DIR [WORKLOAD...]  (crowd longest synth42 synth120)
set -eu
build=${1:?usage: bench/crowd_callgrind.sh BUILD_DIR [WORKLOAD...]}
shift
loads=${*:-crowd longest synth42 synth120}
methods=${METHODS:-fast scan mobb1 mobb}
out=$(mktemp -d)
for w in $loads; do
  printf '%s:' "$w"
  for m in $methods; do
    valgrind --tool=callgrind --callgrind-out-file="$out/cg" --toggle-collect=mobb_run_clip_queries \
      "$build/bench/mobb_crowd_driver" "$w" "$m" 0 >"$out/stdout" 2>"$out/log"
    n=$(sed -n 's/.*): \([0-9]*\) queries.*/\1/p' "$out/stdout")
    total=$(sed -n 's/.*refs: *//p' "$out/log" | tr -d ,)
    printf ' %s %s' "$m" "$((total / n))"
  done
  printf '\n'
done
rm -rf "$out"
