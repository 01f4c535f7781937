#!/bin/sh
# Instructions per query (callgrind, repeatable) for every method on the ~42 s workload.
# Usage: bench/callgrind.sh BUILD_DIR [FPS...]   (Release build; needs valgrind)
# Only mobb_run_queries is measured (setup excluded); N queries over the 4096 fixed placements.
set -eu
build=${1:?usage: bench/callgrind.sh BUILD_DIR [FPS...]}
shift
rates=${*:-30 60}
out=$(mktemp -d)
printf '| method |'; for r in $rates; do printf ' instr/query %s Hz |' "$r"; done; printf '\n|---|'
for r in $rates; do printf -- '---|'; done; printf '\n'
for m in mobb umobb hybrid1 hybrid2 mobb1 umobb1 brute scan fast fcl; do
  case $m in brute|fcl) n=256 ;; *) n=4096 ;; esac
  printf '| %s |' "$m"
  for r in $rates; do
    valgrind --tool=callgrind --callgrind-out-file="$out/cg" --toggle-collect=mobb_run_queries \
      "$build/bench/mobb_query_driver" "$m" "$r" "$n" >/dev/null 2>"$out/log"
    total=$(sed -n 's/.*refs: *//p' "$out/log" | tr -d ,)
    printf ' %s |' "$((total / n))"
  done
  printf '\n'
done
rm -rf "$out"
