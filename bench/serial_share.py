#!/usr/bin/env python3
"""The serial share of the crowd's frame step, profiled: perf samples a one-thread `mobb crowd` run with
call stacks, and each sample whose stack holds the frame step (Simulation::run_batch, or
BroadPhase::expire before it) counts as parallel when it is inside a worker pool job
(util::WorkerPool::work: the code that runs on every thread when there are several) and as serial
otherwise. Prints the shares and the serial part's functions (innermost Simulation:: or BroadPhase::
frame). One thread, so the pool's hand-offs and waits are not in it (`mobb bench scale` measures them).

Usage: bench/serial_share.py BUILD_DIR [AGENTS [SECONDS]]   (default 10000 agents, 20 s; the paper's
density, 12 m^2 per agent, world 3:4 as `mobb bench scale` has it). Needs perf (linux-perf) and
kernel.perf_event_paranoid <= 2.
"""
import collections
import math
import os
import re
import subprocess
import sys
import tempfile

FREQUENCY = 1999  # samples per second: ~2,000 a CPU second, an odd rate so it does not beat with a timer
STACK_BYTES = 16384  # user stack copied per sample for DWARF unwinding: deep enough to reach main


def stacks(text):
    """Each sample's frames (innermost first), from `perf script` output."""
    stack = []
    for line in text.splitlines():
        if not line.strip():
            if stack:
                yield stack
            stack = []
        elif line[0] in " \t":
            stack.append(line.strip())
        else:
            stack = []
    if stack:
        yield stack


def function(frame):
    """The function name of a `perf script` frame line "addr name+0xoff (dso)"."""
    name = re.sub(r"^\S+\s+", "", frame).split(" (")[0]
    return re.sub(r"\+0x[0-9a-f]+$", "", name).split("(")[0]


def classify(text):
    """(samples, frame step samples, parallel samples, Counter of serial samples by function)."""
    total = step = parallel = 0
    serial = collections.Counter()
    for frames in stacks(text):
        total += 1
        names = [function(f) for f in frames]
        if not any(n.endswith(("Simulation::run_batch", "BroadPhase::expire")) for n in names):
            continue
        step += 1
        if any(n.endswith("WorkerPool::work") for n in names):
            parallel += 1
            continue
        serial[next((n for n in names if "Simulation::" in n or "BroadPhase::" in n), "?")] += 1
    return total, step, parallel, serial


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    mobb = os.path.join(sys.argv[1], "src", "app", "mobb")
    agents = int(sys.argv[2]) if len(sys.argv) > 2 else 10000
    seconds = sys.argv[3] if len(sys.argv) > 3 else "20"
    area = agents * 12.0
    world = f"{math.sqrt(area * 3 / 4):.1f}x{math.sqrt(area * 4 / 3):.1f}"
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, "perf.data")
        subprocess.run(["perf", "record", "-q", "-F", str(FREQUENCY), "--call-graph", f"dwarf,{STACK_BYTES}",
                        "-o", data, "--", mobb, "crowd", "--quiet", "--no-motion", "--agents", str(agents),
                        "--world", world, "--seconds", seconds, "--threads", "1"],
                       check=True, stdout=subprocess.DEVNULL)
        script = subprocess.run(["perf", "script", "-i", data, "--no-inline", "--demangle"], check=True,
                                capture_output=True, text=True).stdout
    total, step, parallel, serial = classify(script)
    if step == 0:
        sys.exit("serial_share: no sample in the frame step (no symbols? a build without them?)")
    print(f"mobb crowd --agents {agents} --world {world} --seconds {seconds} --threads 1: {total} samples, "
          f"{step} in the frame step")
    print(f"parallel (in a pool job): {100 * parallel / step:.1f} %, serial: {100 * (step - parallel) / step:.1f} %")
    for name, n in serial.most_common(10):
        print(f"  {100 * n / step:5.1f} %  {name}")


if __name__ == "__main__":
    main()
