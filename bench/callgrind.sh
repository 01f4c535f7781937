#!/bin/sh
# Instructions per query (callgrind, repeatable) of methods on workloads, as a Markdown table.
# Usage: bench/callgrind.sh BUILD_DIR [SET...]       (Release build with MOBB_BUILD_BENCH; needs valgrind)
#   SET: a workload name of mobb_query_driver (seq42-30 seq42-60 table1 table2 synth42 synth120; default
#   seq42-30 seq42-60) or a query-set file (`mobb bench WORKLOAD --save-queries FILE`).
#   METHODS (environment): method keys, default every method (src/bench/method.h).
# Only mobb_run_queries is measured (setup excluded): the first 4096 queries (256 for brute and fcl).
set -eu
build=${1:?usage: bench/callgrind.sh BUILD_DIR [SET...]}
shift
sets=${*:-seq42-30 seq42-60}
methods=${METHODS:-mobb umobb hybrid1 hybrid2 mobb1 umobb1 brute scan sweep fcl}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '| method |'; for s in $sets; do printf ' instr/query %s |' "$(basename "$s")"; done; printf '\n|---|'
for s in $sets; do printf -- '---:|'; done; printf '\n'
for m in $methods; do
  case $m in brute|fcl) n=256 ;; *) n=4096 ;; esac
  printf '| %s |' "$m"
  for s in $sets; do
    if valgrind --tool=callgrind --callgrind-out-file="$out/cg" --toggle-collect=mobb_run_queries \
         "$build/bench/mobb_query_driver" "$s" "$m" "$n" >"$out/stdout" 2>"$out/log"; then
      done_n=$(sed -n 's/^queries \([0-9]*\) .*/\1/p' "$out/stdout")
      total=$(sed -n 's/.*refs: *//p' "$out/log" | tr -d ,)
      printf ' %s |' "$((total / done_n))"
    else
      printf ' - |'
    fi
  done
  printf '\n'
done
