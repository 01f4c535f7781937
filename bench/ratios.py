#!/usr/bin/env python3
"""Side-by-side table of whole-query times from one mobb_bench JSON run (bench/README.md).

Usage: bench/ratios.py RUN.json
Reads the Seq42/<method>/<fps> rows (median aggregate if repetitions were used) and prints, per
method and rate, microseconds per query, the ratio to the circle sweep, and the positive/agree shares.
"""
import json
import sys

METHODS = ["mobb", "umobb", "hybrid1", "hybrid2", "mobb1", "umobb1", "brute", "scan", "sweep", "fcl"]  # Method order
SWEEP = METHODS.index("sweep")


def main(path):
    with open(path) as f:
        run = json.load(f)
    rows = {}
    for b in run["benchmarks"]:
        name = b.get("run_name", b["name"])
        if not name.startswith("Seq42/"):
            continue
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        _, m, fps = name.split("/")[:3]
        scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[b["time_unit"]]
        rows[(int(m), int(fps))] = (b["cpu_time"] * scale, b.get("positive", 0.0), b.get("agree", 0.0))
    rates = sorted({fps for _, fps in rows})
    head = "| method |" + "".join(f" us/query {r} Hz | x sweep {r} Hz |" for r in rates) + " positive | agree |"
    print(head)
    print("|" + "---|" * (1 + 2 * len(rates) + 2))
    for m, name in enumerate(METHODS):
        cells = []
        for r in rates:
            if (m, r) not in rows or (SWEEP, r) not in rows:
                cells += ["-", "-"]
                continue
            t = rows[(m, r)][0]
            cells += [f"{t:.3f}", f"{t / rows[(SWEEP, r)][0]:.1f}"]
        pos = rows.get((m, rates[0]), (0, 0, 0))
        print(f"| {name} | " + " | ".join(cells) + f" | {pos[1]:.3f} | {pos[2]:.4f} |")


if __name__ == "__main__":
    main(sys.argv[1])
