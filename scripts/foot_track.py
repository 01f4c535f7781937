#!/usr/bin/env python3
"""One foot's track through a clip start, blended with feet free and locked (docs/export.md's picture).

    PYTHONPATH=build/python scripts/foot_track.py OUT.png

Runs the 12-agent, 30 s crowd of docs/export.md (`mobb.crowd(agents=12, world=(12, 12), seconds=30,
seed=11)`), poses agent 0's left ankle at frames 136..160 with `mobb.crowd_poses` (lock_feet True and
False) and draws both tracks from above, in centimetres from the ankle at frame 143, the clip start
(frame 146) marked. Needs the mocap (../shared/mocap or $MOBB_DATA) and matplotlib.
"""
import json
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import mobb  # noqa: E402

FRAMES = range(136, 161)
ORIGIN, CLIP_START = 143, 146


def track(record, dt, ankle, lock):
    poses = mobb.crowd_poses(record, [0], [k * dt for k in FRAMES], lock_feet=lock)[0, :, ankle, :2]
    return (poses - poses[FRAMES.index(ORIGIN)]) * 100.0


def main(out):
    with tempfile.TemporaryDirectory() as tmp:
        record = os.path.join(tmp, "r.json")
        mobb.crowd(agents=12, world=(12, 12), seconds=30, seed=11, record=record)
        names, _ = mobb.crowd_joints(record)
        ankle = names.index("CC_Base_L_Foot") if "CC_Base_L_Foot" in names else names.index("LeftFoot")
        with open(record) as f:
            dt = json.load(f)["dt"]
        free, locked = track(record, dt, ankle, False), track(record, dt, ankle, True)
    fig, ax = plt.subplots(figsize=(6, 4.2), dpi=100)
    for xy, style, label in ((free, "o-", "blended, feet free"), (locked, "s-", "blended, feet locked")):
        ax.plot(xy[:, 0], xy[:, 1], style, ms=3, label=label)
    k = FRAMES.index(CLIP_START)
    ax.plot(free[k, 0], free[k, 1], "k*", ms=10, label=f"clip start (frame {CLIP_START})")
    ax.set_xlabel("x (cm from frame 143)")
    ax.set_ylabel("y (cm)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_title(f"agent 0's left ankle, frames {FRAMES[0]}-{FRAMES[-1]}, seen from above")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
