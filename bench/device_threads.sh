#!/usr/bin/env bash
# Issue 46 on a lent many-core machine (the `device` tool, 15 minutes in all): two crowd-only builds' thread
# tables side by side, interleaved, and whole records compared across thread counts. About 6 minutes on 16 cores.
#
#   bench/device_threads.sh BEFORE AFTER LIBDIR OUT
#
# BEFORE, AFTER: `mobb` binaries of two commits, each built here with
#   scripts/build build-dev -DMOBB_BUILD_VIEWER=OFF -DMOBB_BUILD_TESTS=OFF -DMOBB_BUILD_BENCH=OFF
# LIBDIR: the shared libraries they link that the machine lacks (`ldd`, less libc and libm), carried with them.
# OUT: a folder for the tables and digests ($OUT on the device).
set -euo pipefail
[ $# -eq 4 ] || { echo "usage: $0 BEFORE AFTER LIBDIR OUT" >&2; exit 2; }
before=$1 after=$2 out=$4
export LD_LIBRARY_PATH=$3${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} MOBB_DATA=${MOBB_DATA:-../shared/mocap}
mkdir -p "$out"
nproc > "$out/nproc.txt"
table() {  # BIN NAME AGENTS SECONDS
  "$1" bench scale --agents "$3" --seconds "$4" --threads 1,2,4,8,16 --repeats 1 2>/dev/null >"$out/$2-$3x$4.md"
  grep -E "simulation s \||speed-up over" "$out/$2-$3x$4.md" | sed "s/^/$2 $3x$4 /"
}
for round in 1 2; do
  table "$before" "before$round" 100000 20
  table "$after" "after$round" 100000 20
done
table "$before" before 10000 60
table "$after" after 10000 60
for t in 1 16; do  # whole records, byte for byte, of the build after
  "$after" crowd --no-motion --agents 3000 --world 164x219 --seconds 10 --threads $t --record "$out/w$t.json" >/dev/null 2>&1
  "$after" crowd --no-motion --scenario assets/scenarios/evacuation_exit.json --seed 1 --threads $t \
    --record "$out/e$t.json" >/dev/null 2>&1
done
sha256sum "$out"/w*.json "$out"/e*.json | sed 's|  .*/| |' | tee "$out/digests.txt"
rm -f "$out"/w*.json "$out"/e*.json
