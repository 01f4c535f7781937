#!/usr/bin/env python3
"""Loads two clips, places them so that the walkers cross, finds the first time they collide and plots
both paths on the ground with matplotlib.

    PYTHONPATH=build/python /usr/bin/python3 examples/first_collision.py [A B] [--out FILE.png]

A and B default to two CMU walks of the mocap folder ($MOBB_DATA or ../shared/mocap).
Placements are (x, y, theta, t0) in metres, metres, radians and seconds."""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import mobb  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def data_file(name):
    folder = os.environ.get("MOBB_DATA") or os.path.join(HERE, "..", "..", "shared", "mocap")
    return os.path.join(folder, name)


def placed(path, place):
    """World ground positions (n, 2) of a path (n, 4 rows t, x, y, r) placed at (x, y, theta, t0)."""
    x, y, theta, _ = place
    c, s = math.cos(theta), math.sin(theta)
    return np.column_stack([c * path[:, 1] - s * path[:, 2] + x, s * path[:, 1] + c * path[:, 2] + y])


def first_collision(a, pa, b, pb):
    """Global time (s) of the first sample of a that collides with b, with the samples (i, j); None when
    they never collide. clearance() is negative exactly where collide() finds a collision."""
    if not mobb.collide(mobb.Tree(a), pa, mobb.Tree(b), pb):
        return None
    c = mobb.clearance(a, pa, b, pb)
    k = int(np.argmax(c["gap"] < 0))
    return float(c["t"][k]), int(c["i"][k]), int(c["j"][k])


def plot(a, pa, b, pb, hit, out):
    fig, ax = plt.subplots(figsize=(7, 5.2), dpi=110)
    for clip, place, colour, label in ((a, pa, "tab:blue", "A"), (b, pb, "tab:orange", "B")):
        xy = placed(clip.path, place)
        name = os.path.basename(clip.info["file"])
        ax.plot(xy[:, 0], xy[:, 1], color=colour, lw=1.5, label=f"{label}: {name} from t = {place[3]:g} s")
        ax.plot(*xy[0], "o", color=colour, ms=5)
        ax.annotate("start", xy[0], textcoords="offset points", xytext=(4, 4), color=colour, fontsize=8)
    if hit:
        t, i, j = hit
        for clip, place, k, colour in ((a, pa, i, "tab:blue"), (b, pb, j, "tab:orange")):
            centre = placed(clip.path[k:k + 1], place)[0]
            ax.add_patch(plt.Circle(centre, clip.path[k, 3], color=colour, alpha=0.3))
        ax.set_title(f"First collision at t = {t:.3f} s (samples {i} of A, {j} of B)")
    else:
        ax.set_title("No collision")
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(out)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("clips", nargs="*", help="two clips (default: cmu/002_01.bvh and cmu/005_01.bvh)")
    p.add_argument("--out", default="first_collision.png", help="PNG to write")
    args = p.parse_args()
    files = args.clips or [data_file("cmu/002_01.bvh"), data_file("cmu/005_01.bvh")]
    if len(files) != 2:
        p.error("give two clips or none")
    a, b = mobb.load(files[0]), mobb.load(files[1])
    # A as recorded (it walks along -y); B turned a quarter turn counter-clockwise (so it walks along +x),
    # 1.5 m to the left of A's way, starting 0.5 s later.
    pa = (0.0, 0.0, 0.0, 0.0)
    pb = (-1.5, -2.0, math.pi / 2, 0.5)
    hit = first_collision(a, pa, b, pb)
    print("first collision:", "none" if hit is None else f"t = {hit[0]:.3f} s (samples {hit[1]} of A, {hit[2]} of B)")
    plot(a, pa, b, pb, hit, args.out)
    print("wrote", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
