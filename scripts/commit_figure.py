#!/usr/bin/env python3
"""How a frame's choice points commit (docs/crowd.md, "Threads and determinism"): a schematic.

    scripts/commit_figure.py OUT.png

Top: one frame's batch in agent order, each position current (its evaluation still holds), stale (a plan
committed before it in the frame touched what it queried: evaluated again) or rerouting others (the right of
way: it commits alone); the runs between them commit as one parallel step. Bottom: the same frame on two
threads, step by step (Simulation::run_batch in src/crowd/sim/crowd.cpp, commit_run in commit.cpp). The
sizes are drawn, not measured: the text beside the figure gives the measured ones. Needs matplotlib.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

CURRENT, STALE, REROUTE = "#9ecae1", "#e6550d", "#fdae6b"
PARALLEL, SERIAL, AGAIN = "#3182bd", "#636363", "#e6550d"
POSITIONS = 36
STALE_AT = {9, 21}  # positions a plan committed before them touched
REROUTE_AT = {27}  # a position whose plan reroutes other agents
TOUCHED_BY = {9: 4, 21: 13}  # the earlier position whose plan touched each stale one


def runs():
    """The runs of positions committed together: [from, to) between stale and rerouting positions."""
    out, start = [], 0
    for i in range(POSITIONS):
        if i in STALE_AT:
            out.append((start, i))
            start = i
        if i in REROUTE_AT:
            out.append((start, i))
            out.append((i, i + 1))
            start = i + 1
    out.append((start, POSITIONS))
    return [r for r in out if r[1] > r[0]]


def draw_batch(ax):
    for i in range(POSITIONS):
        colour = STALE if i in STALE_AT else REROUTE if i in REROUTE_AT else CURRENT
        ax.add_patch(Rectangle((i, 0), 0.9, 1, color=colour))
    for i, by in TOUCHED_BY.items():
        ax.annotate("", xy=(i + 0.45, 1.05), xytext=(by + 0.45, 1.05),
                    arrowprops=dict(arrowstyle="->", color=STALE, connectionstyle="arc3,rad=-0.35"))
    for k, (a, b) in enumerate(runs()):
        ax.plot([a + 0.1, b - 0.2], [-0.35, -0.35], color=PARALLEL if b - a > 1 else SERIAL, lw=3)
        ax.text((a + b) / 2 - 0.05, -0.75, f"run {k + 1}" + ("" if b - a > 1 else " (alone)"), ha="center",
                va="top", fontsize=8)
    ax.text(0, 1.75, "one frame's choice points in agent order (a position per agent at a choice point)", fontsize=9)
    ax.legend(handles=[Rectangle((0, 0), 1, 1, color=c) for c in (CURRENT, STALE, REROUTE)],
              labels=["current: its evaluation still holds", "stale: a plan before it touched what it queried",
                      "reroutes others (right of way)"], loc="lower center", fontsize=7, ncol=3, frameon=False,
              bbox_to_anchor=(0.5, -0.12))
    ax.set_xlim(-0.5, POSITIONS + 0.5)
    ax.set_ylim(-1.6, 2.0)
    ax.axis("off")


# The frame on two threads: (label, start, length, threads) with threads 2 for a parallel step, 1 for the
# calling thread alone.
STEPS = [
    ("evaluate all", 0.0, 6.0, 2),
    ("boxes, grid", 6.0, 0.8, 2),
    ("touched?", 6.8, 0.6, 2),
    ("run 1", 7.6, 1.3, 2),
    ("again", 8.9, 0.7, 2),
    ("run 2", 9.6, 1.1, 2),
    ("again", 10.7, 0.7, 2),
    ("run 3", 11.4, 0.8, 2),
    ("alone", 12.2, 0.3, 1),
    ("run 5", 12.5, 1.0, 2),
    ("broad phase", 13.5, 0.9, 2),
]


def draw_threads(ax):
    for label, start, length, threads in STEPS:
        colour = AGAIN if label == "again" else PARALLEL if threads == 2 else SERIAL
        for lane in range(threads):
            ax.add_patch(Rectangle((start, 1 - lane), length - 0.05, 0.8, color=colour, alpha=0.85))
        ax.text(start + length / 2, 1.95, label, ha="center", va="bottom", fontsize=7, rotation=30)
    # The thin serial parts between parallel steps: walking the positions, the prefix sums, what goes in order.
    for _, start, _, threads in STEPS[3:]:
        ax.add_patch(Rectangle((start - 0.06, 1), 0.06, 0.8, color=SERIAL))
    ax.text(-0.2, 1.4, "thread 0", ha="right", va="center", fontsize=8)
    ax.text(-0.2, 0.4, "thread 1", ha="right", va="center", fontsize=8)
    ax.text(0, -0.45, "(1) every choice point evaluated against the frame's start   (2) the boxes their plans take   "
            "(3) which an earlier plan touched   (4) in order: runs commit in parallel,\nstale positions are "
            "evaluated again (with the next stale ones, in parallel), a rerouting one commits alone; then the "
            "broad phase takes the frame's pieces", fontsize=7, va="top")
    ax.set_xlim(-1.6, 14.6)
    ax.set_ylim(-1.2, 2.9)
    ax.axis("off")


def main(out):
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(10, 4.6), dpi=110, gridspec_kw={"height_ratios": [1, 1.1]})
    draw_batch(top)
    draw_threads(bottom)
    fig.suptitle("A frame's commits: in agent order where plans can meet, in parallel where they cannot", fontsize=10)
    fig.tight_layout()
    fig.savefig(out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
