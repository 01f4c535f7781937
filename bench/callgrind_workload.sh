#!/bin/sh
# Instructions per query (callgrind, repeatable) for every method of one `mobb bench` workload, merged
# into bench/results/WORKLOAD.json ("instructions_per_query", "callgrind_queries" per row) and appended
# to bench/results/WORKLOAD.md.
# Usage: bench/callgrind_workload.sh WORKLOAD BUILD_DIR [QUERY_SET]
#   WORKLOAD: table1 | table2 | synth42 | synth120 | scale (needs bench/results/WORKLOAD.json from the
#   same build)
#   QUERY_SET: the file of `mobb bench WORKLOAD --save-queries FILE`; without it the set is regenerated
#   with the default options (one timed pass, output discarded). For scale it is the FILE prefix: the
#   sets FILE.<agents> (a sample of each crowd's clip-against-clip queries), on which "MOBB" (the paper's
#   tree) and "circle sweep" (the library's fastest, the crowd's narrow phase) are counted.
# Release build and valgrind needed. Only mobb_run_queries is measured (loading, preparing the method
# excluded): the first N queries of the set, N = 5000 (300 for brute force and FCL, which are slow under
# callgrind), or all when fewer.
set -eu
workload=${1:?usage: bench/callgrind_workload.sh WORKLOAD BUILD_DIR [QUERY_SET]}
build=${2:?usage: bench/callgrind_workload.sh WORKLOAD BUILD_DIR [QUERY_SET]}
root=$(cd "$(dirname "$0")/.." && pwd)
json="$root/bench/results/$workload.json"
md="$root/bench/results/$workload.md"
driver="$build/bench/mobb_query_driver"
[ -f "$json" ] || { echo "no $json: run mobb bench $workload --json first" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
set_file=${3:-}
if [ -z "$set_file" ]; then
  set_file="$tmp/set.txt"
  case $workload in
    scale) "$build/src/app/mobb" bench scale --quiet --repeats 1 --save-queries "$set_file" >/dev/null ;;
    *) "$build/src/app/mobb" bench "$workload" --quiet --passes 1 --save-queries "$set_file" >/dev/null ;;
  esac
fi
# count METHOD N SET LABEL: one callgrind run, appended to $tmp/counts as "LABEL<TAB>method<TAB>instr<TAB>queries".
count() {
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" --toggle-collect=mobb_run_queries \
    "$driver" "$3" "$1" "$2" >"$tmp/out" 2>"$tmp/log"
  total=$(sed -n 's/.*refs: *//p' "$tmp/log" | tr -d ,)
  done_n=$(sed -n 's/^queries \([0-9]*\) .*/\1/p' "$tmp/out")
  printf '%s\t%s\t%s\t%s\n' "$4" "$1" "$total" "$done_n" >> "$tmp/counts"
  printf '%s %s: %s instructions / %s queries\n' "$4" "$1" "$total" "$done_n" >&2
}
: > "$tmp/counts"
if [ "$workload" = scale ]; then
  for n in $(python3 -c 'import json,sys; [print(r["agents"]) for r in json.load(open(sys.argv[1]))["rows"]]' "$json"); do
    count MOBB 5000 "$set_file.$n" "$n"
    count "circle sweep" 5000 "$set_file.$n" "$n"
  done
  python3 "$root/bench/merge_callgrind.py" "$json" "$md" "$tmp/counts" "$(valgrind --version)"
  exit 0
fi
python3 -c 'import json,sys; [print(r["method"]) for r in json.load(open(sys.argv[1]))["rows"] if r.get("measured", True) and r["method"] != "frame stepping"]' "$json" > "$tmp/methods"
while IFS= read -r m; do
  case $m in "brute force"|FCL) n=300 ;; *) n=5000 ;; esac
  count "$m" "$n" "$set_file" "-"
done < "$tmp/methods"
python3 "$root/bench/merge_callgrind.py" "$json" "$md" "$tmp/counts" "$(valgrind --version)"
