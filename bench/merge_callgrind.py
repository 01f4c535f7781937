#!/usr/bin/env python3
"""Merges callgrind counts into a results JSON and appends them to its Markdown (callgrind_workload.sh).

Usage: merge_callgrind.py RESULTS.json RESULTS.md COUNTS VALGRIND_VERSION
COUNTS: lines "label<TAB>method<TAB>instructions<TAB>queries"; label "-" for the method tables, where
"instructions_per_query", "callgrind_queries" and "x_sweep_instructions" (method / circle sweep) go to
the rows of that method; for scale the label is the row's agent count, and the row gets the paper's MOBB
tree as "instructions_per_query" and the circle sweep (the crowd's own query) as
"instructions_per_query_sweep". Adds
a "callgrind" note and a Markdown table (replacing any earlier one)."""
import json
import sys

MARK = "\n#### Instructions per query (callgrind)\n"
SWEEP = "circle sweep"


def append_markdown(md_path, version, lines):
    text = open(md_path).read()
    if MARK in text:
        text = text[: text.index(MARK)]
    text = text.rstrip("\n") + "\n" + MARK + "\n" + version + ", Release, setup excluded.\n\n" + "\n".join(lines) + "\n"
    open(md_path, "w").write(text)


def write_json(path, data):
    with open(path, "w") as f:
        json.dump(data, f, indent=2)
        f.write("\n")


def merge_scale(data, counts, version):
    lines = ["| agents | MOBB (the paper's tree) instr / query | circle sweep (the crowd's query) instr / query | queries sampled |",
             "|---:|---:|---:|---:|"]
    for row in data["rows"]:
        label = str(row["agents"])
        crowd, fast = counts.get((label, "MOBB")), counts.get((label, SWEEP))
        if not crowd or not fast or crowd[1] == 0:
            continue
        row["instructions_per_query"] = round(crowd[0] / crowd[1], 1)
        row["instructions_per_query_sweep"] = round(fast[0] / fast[1], 1)
        row["callgrind_queries"] = crowd[1]
        lines.append("| %s | %.0f | %.0f | %d |" % (label, crowd[0] / crowd[1], fast[0] / fast[1], crowd[1]))
    data["notes"]["callgrind"] = (version + ", Release build; up to 5,000 queries sampled evenly from a logged "
                                  "1-thread run of each size, the query loop only (bench/query_driver.cpp)")
    return lines


def main():
    path, md_path, counts_path, version = sys.argv[1:5]
    raw = {}
    for line in open(counts_path):
        label, method, total, queries = line.rstrip("\n").split("\t")
        raw[(label, method)] = (int(total), int(queries))
    data = json.load(open(path))
    if data.get("workload") == "scale":
        lines = merge_scale(data, raw, version)
        write_json(path, data)
        append_markdown(md_path, version, lines)
        return
    counts = {m: v for (label, m), v in raw.items()}
    per = {m: t / q for m, (t, q) in counts.items() if q > 0}
    sweep = per.get(SWEEP)
    for row in data["rows"]:
        if row["method"] in per:
            row["instructions_per_query"] = round(per[row["method"]], 1)
            row["callgrind_queries"] = counts[row["method"]][1]
            if sweep:
                row["x_sweep_instructions"] = round(per[row["method"]] / sweep, 3)
    data["notes"]["callgrind"] = (version + ", Release build; instructions of the query loop only "
                                  "(bench/query_driver.cpp), the first callgrind_queries queries of the set")
    write_json(path, data)
    lines = ["| Method | instructions / query | x sweep | queries |", "|---|---:|---:|---:|"]
    for row in data["rows"]:
        if row["method"] in per:
            ratio = "%.2f" % (per[row["method"]] / sweep) if sweep else "-"
            lines.append("| %s | %.0f | %s | %d |" % (row["method"], per[row["method"]], ratio, counts[row["method"]][1]))
    append_markdown(md_path, version, lines)


if __name__ == "__main__":
    main()
