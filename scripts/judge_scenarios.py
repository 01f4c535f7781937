#!/usr/bin/env python3
"""Runs crowd scenarios and judges each run from its record alone (issue 28).

    scripts/judge_scenarios.py [FOLDER | FILE.json ...] [--mobb PATH] [--seeds 1 2 3] [--out DIR] [--json]

For every scenario file (*.json of each folder, sorted; default assets/scenarios) and seed it runs
    mobb crowd --scenario F --seed K --quiet --threads 1 --record R.json
two at a time (from the repository root, so the default graph is found; MOBB=PATH is set in its
environment), then reads R.json (layout: include/mobb/crowd/record/record.h) and judges:

  pass     no two agents' disks overlap at any frame (|p_a - p_b| < r_a + r_b); no disk on an obstacle (the
           centre inside the polygon, or closer to its boundary than r) or, in a walled world, past the world
           rectangle (x - r < x0, ...; unwalled: the centre outside it); and every agent is within 1 m of its
           goal (distance < 1) from some frame at or before its deadline to the end of the run - or, for
           an agent that leaves the run at its goal ("left_frame"), to the frame it left. With goals in
           turn ("goals"), the last counts from the frame the one before was first within 1 m. Deadline:
           min(time limit, start_time + 3 d / 1.3 m/s + 20 s), d the straight distance from the start
           through the goals in turn.
  goal ok  agents meeting the goal rule above; reached: agents within 1 m of the goal at some frame. A
           failed goal is one of: never within 1 m; late (first within 1 m after the deadline); in time but
           out of the 1 m circle at some later frame (with how far it went, and whether it was back in).
  t/t0     mean over the agents that reached their goal of (first time within 1 m - start_time) / (d / v),
           d the straight start-goal distance, v the graph's mean clip
           speed: from the `mobb crowd` line "speed ... of the graph's mean clip speed (X m/s)", else
           computed from the record's graph file (path length / duration, mean over clips), else 1.0 m/s
           assumed; the header says which.
  idle %   of agent time from start_time until the agent is first within 1 m of its goal (or the end): frames where the
           root moved under 0.1 m/s over a 0.5 s window (15 frames at 30 fps) round the frame (the clips' roots placed
           from the record where its graph centres the disks on the body).
  wall s   wall-clock seconds of the mobb run.
"""
import os
import sys

try:
    import numpy as np
except ImportError:  # e.g. a pyenv python3 without numpy: Debian's has it (python3-numpy)
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    raise

import argparse
import concurrent.futures
import glob
import json
import math
import re
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GOAL_RADIUS = 1.0     # m
IDLE_SPEED = 0.1      # m/s
IDLE_WINDOW = 0.5     # s
DEADLINE_SPEED = 1.3  # m/s
SPEED_LINE = re.compile(r"of the graph's mean clip speed \(([-+0-9.eE]+) m/s\)")


def graph_clips(path):
    """The clips of the record's graph file, or None when it cannot be read."""
    try:
        with open(path if os.path.isabs(path) else os.path.join(ROOT, path)) as f:
            return json.load(f)["clips"]
    except (OSError, KeyError, ValueError):
        return None


def clip_root(c):
    """A clip's root on the ground per sample, [n, 2]: its "root" where its disks are centred on the body."""
    return np.asarray(c["root"] if "root" in c else [p[:2] for p in c["path"]], dtype=float)


def graph_speed_from_file(path):
    """The graph's mean clip speed (root path length / duration, mean over clips), or None."""
    clips = graph_clips(path)
    try:
        speeds = [float(np.hypot(*np.diff(clip_root(c), axis=0).T).sum()) / c["duration"] for c in clips]
        return sum(speeds) / len(speeds) if speeds else None
    except (TypeError, KeyError, ValueError, IndexError, ZeroDivisionError):
        return None


def root_tracks(rec, x, y):
    """Each agent's root per frame ([n, frames] x and y): the samples' centres, or, where the record's graph
    centres its disks on the body, its clips' roots placed as the disks are."""
    clips = graph_clips(rec.get("graph", ""))
    if not clips or not any("root" in c for c in clips):
        return x, y
    rx, ry = np.full(x.shape, np.nan), np.full(y.shape, np.nan)
    for a, t in enumerate(rec["tracks"]):
        n = len(t["samples"])
        placed = t["clips"]
        for k, pc in enumerate(placed):
            f0, f1 = pc["start"], min(n, placed[k + 1]["start"] if k + 1 < len(placed) else n)
            if f1 <= f0:
                continue
            root = clip_root(clips[pc["clip"]])[:f1 - f0]
            px, py, theta = pc["place"][:3]
            c, s = math.cos(theta), math.sin(theta)
            rx[a, f0:f1] = px + c * root[:, 0] - s * root[:, 1]
            ry[a, f0:f1] = py + s * root[:, 0] + c * root[:, 1]
    return rx, ry


def polygon_hits(poly, x, y, r):
    """Disks (x, y, r: arrays of one shape) overlapping the polygon (two vertices: a segment)."""
    v = np.asarray(poly, dtype=float)
    n = len(v)
    dist = np.full(x.shape, np.inf)
    inside = np.zeros(x.shape, dtype=bool)
    for k in range(n if n > 2 else 1):
        ax, ay = v[k]
        bx, by = v[(k + 1) % n]
        ex, ey = bx - ax, by - ay
        length2 = ex * ex + ey * ey
        u = np.clip(((x - ax) * ex + (y - ay) * ey) / length2, 0, 1) if length2 > 0 else np.zeros(x.shape)
        dist = np.minimum(dist, np.hypot(x - ax - u * ex, y - ay - u * ey))
        if n > 2 and ey != 0:
            crosses = ((ay > y) != (by > y)) & (x < ax + (y - ay) * ex / ey)
            inside ^= crosses
    return inside | (dist < r)


def judge(record_path, scenario, stdout):
    with open(record_path) as f:
        rec = json.load(f)
    dt, frames = float(rec["dt"]), int(rec["frames"])
    tracks = rec["tracks"]
    n = len(tracks)
    # An agent that left the run (at_goal "leave") has samples up to its left_frame: NaN after, which
    # meets nothing.
    s = np.full((n, frames, 4), np.nan)
    for a, t in enumerate(tracks):
        if t["samples"]:
            s[a, :len(t["samples"])] = np.asarray(t["samples"], dtype=float)
    x, y, r = s[:, :, 1], s[:, :, 2], s[:, :, 3]
    rx, ry = root_tracks(rec, x, y)  # how an agent moves is its root's; where it stands, its disk's
    reasons, kinds = [], []

    # Agent pairs: every frame, every pair (frame-major blocks of the N x N distance matrix).
    contact_frames, first, deepest = 0, None, 0.0
    if n > 1:
        upper = np.triu(np.ones((n, n), dtype=bool), 1)
        xt, yt, rt = x.T, y.T, r.T
        block = max(1, 4_000_000 // (n * n))
        for f0 in range(0, frames, block):
            bx, by, br = xt[f0:f0 + block], yt[f0:f0 + block], rt[f0:f0 + block]
            d = np.hypot(bx[:, :, None] - bx[:, None, :], by[:, :, None] - by[:, None, :])
            reach = br[:, :, None] + br[:, None, :]
            hit = (d < reach) & upper
            if hit.any():
                contact_frames += int(hit.sum())
                deepest = max(deepest, float((reach - d)[hit].max()))
                if first is None:
                    f, a, b = (int(v[0]) for v in np.nonzero(hit))
                    first = (f0 + f, a, b)
    if contact_frames:
        f, a, b = first
        reasons.append(f"{contact_frames} contact pair-frames (first t={f * dt:.1f}s a{a}-a{b}; deepest {deepest:.3f} m)")
        kinds.append("contact")

    # Obstacles and walls.
    w = rec["world"]
    x0, y0, x1, y1 = (0.0, 0.0, w[0], w[1]) if len(w) == 2 else w
    solid_hits = []  # (agent-frames, first frame, agent, what)
    for k, poly in enumerate(rec.get("obstacles", [])):
        lo = np.array(poly, dtype=float).min(axis=0)
        hi = np.array(poly, dtype=float).max(axis=0)
        near = (x + r > lo[0]) & (x - r < hi[0]) & (y + r > lo[1]) & (y - r < hi[1])
        if not near.any():
            continue
        hit = np.zeros(x.shape, dtype=bool)
        hit[near] = polygon_hits(poly, x[near], y[near], r[near])
        if hit.any():
            a, f = np.argwhere(hit)[np.argmin(np.argwhere(hit)[:, 1])]
            solid_hits.append((int(hit.sum()), int(f), int(a), f"obstacle {k}"))
    if rec.get("walls", False):
        out = (x - r < x0) | (x + r > x1) | (y - r < y0) | (y + r > y1)
        what = "wall"
    else:
        out = (x < x0) | (x > x1) | (y < y0) | (y > y1)
        what = "outside the world"
    if out.any():
        a, f = np.argwhere(out)[np.argmin(np.argwhere(out)[:, 1])]
        solid_hits.append((int(out.sum()), int(f), int(a), what))
    if solid_hits:
        count = sum(h[0] for h in solid_hits)
        _, f, a, what = min(solid_hits, key=lambda h: h[1])
        reasons.append(f"{count} agent-frames on solids (first t={f * dt:.1f}s a{a} on {what})")
        kinds.append("solid")

    # Goals.
    agents = scenario.get("agents", [])
    time_limit = float(scenario.get("time_limit", frames * dt))
    goals_of = lambda t: [t["goal"]] if "goal" in t else t.get("goals", [])
    goal_agents = [a for a in range(n) if goals_of(tracks[a])]
    late, never, left = [], [], []
    settle = np.full(n, -1)
    ratios, idle, counted = [], 0, 0
    speed = None
    m = SPEED_LINE.search(stdout or "")
    if m:
        speed, speed_source = float(m.group(1)), "stdout"
    else:
        speed = graph_speed_from_file(rec.get("graph", ""))
        speed_source = "graph file" if speed else "assumed"
        speed = speed or 1.0
    window = max(1, int(round(IDLE_WINDOW / dt)))
    idx = np.arange(frames)
    lo_i = np.clip(idx - window // 2, 0, frames - 1)
    hi_i = np.clip(lo_i + window, 0, frames - 1)
    span = np.maximum(hi_i - lo_i, 1) * dt
    for a in range(n):
        start_time = float(agents[a].get("start_time", 0)) if a < len(agents) else 0.0
        first_frame = min(frames, int(math.ceil(start_time / dt - 1e-9)))
        end = frames
        if goals_of(tracks[a]):
            goals = np.asarray(goals_of(tracks[a]), dtype=float)
            g = goals[-1]
            start = np.asarray(agents[a]["start"], dtype=float) if a < len(agents) else s[a, 0, 1:3]
            d0 = float(np.hypot(*(goals[0] - start)) + sum(np.hypot(*(goals[k + 1] - goals[k]))
                                                            for k in range(len(goals) - 1)))
            deadline = min(time_limit, start_time + 3 * d0 / DEADLINE_SPEED + 20)
            # Each goal within 1 m in turn; the last from the frame the one before was reached on.
            before = 0
            for k in range(len(goals) - 1):
                near = np.nonzero(np.hypot(x[a, before:] - goals[k][0], y[a, before:] - goals[k][1]) < GOAL_RADIUS)[0]
                before = before + int(near[0]) if len(near) else frames
            dist = np.hypot(x[a] - g[0], y[a] - g[1])
            inside = dist < GOAL_RADIUS
            inside[:before] = False
            # An agent that left the run is judged up to the frame it left (its samples end there).
            last = tracks[a].get("left_frame", frames)
            inside = inside[:last]
            if inside.any():
                arrival = int(np.argmax(inside))
                end = arrival
                t_arrival = arrival * dt
                if d0 > 0:
                    ratios.append(max(0.0, t_arrival - start_time) / (d0 / speed))
                outside = np.nonzero(~inside)[0]
                settle[a] = (int(outside[-1]) + 1 if len(outside) else 0) if inside[-1] else -1
                if "left_frame" in tracks[a]:
                    settle[a] = arrival  # it left the run at its goal: nothing after to stay for
                if t_arrival > deadline + 1e-9:
                    late.append((a, t_arrival, deadline))
                elif settle[a] < 0 or settle[a] * dt > deadline + 1e-9:
                    left.append((a, float(dist[arrival:].max()), bool(inside[-1])))
            else:
                never.append(a)
        if end > first_frame:
            moved = np.hypot(rx[a, hi_i] - rx[a, lo_i], ry[a, hi_i] - ry[a, lo_i]) / span
            idle += int((moved[first_frame:end] < IDLE_SPEED).sum())
            counted += end - first_frame
    goal_fail = []
    if never:
        goal_fail.append(f"{len(never)} never within 1 m (a{never[0]}" + (", ..." if len(never) > 1 else "") + ")")
    if late:
        a, t, dl = max(late, key=lambda v: v[1] - v[2])
        goal_fail.append(f"{len(late)} late (worst a{a} first within 1 m at {t:.1f}s > {dl:.1f}s)")
    if left:
        a, far, back = max(left, key=lambda v: v[1])
        goal_fail.append(f"{len(left)} in time but out of the 1 m circle later (worst a{a} to {far:.2f} m"
                         + (", back by the end)" if back else ", still out at the end)"))
    if goal_fail:
        reasons.append("goals: " + "; ".join(goal_fail))
        kinds += [k for k, v in (("never", never), ("late", late), ("left", left)) if v]
    reached = len(goal_agents) - len(never)
    return {
        "passed": not reasons, "reasons": reasons, "kinds": kinds,
        "agents": n, "goal_agents": len(goal_agents), "reached": reached,
        "goal_ok": len(goal_agents) - len(never) - len(left) - len(late),
        "never": len(never), "left": len(left), "late": len(late),
        "contact_pair_frames": contact_frames, "max_penetration": deepest,
        "solid_agent_frames": sum(h[0] for h in solid_hits),
        "time_ratio": float(np.mean(ratios)) if ratios else None,
        "graph_speed": speed, "speed_source": speed_source,
        "idle_share": idle / counted if counted else 0.0,
        "frames": frames, "dt": dt,
    }


def run_one(task):
    mobb, scenario_file, seed, record, label = task
    with open(scenario_file) as f:
        scenario = json.load(f)
    cmd = [mobb, "crowd", "--scenario", os.path.abspath(scenario_file), "--seed", str(seed), "--quiet",
           "--threads", "1", "--record", record]
    env = dict(os.environ, MOBB=mobb)
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=1800)
        wall = time.perf_counter() - t0
    except subprocess.TimeoutExpired:
        return {"label": label, "file": scenario_file, "seed": seed, "passed": False, "kinds": ["error"],
                "reasons": ["mobb timed out (1800 s)"], "wall": time.perf_counter() - t0}
    base = {"label": label, "file": scenario_file, "seed": seed, "wall": wall, "record": record}
    if p.returncode != 0 or not os.path.exists(record):
        err = (p.stderr.strip().splitlines() or ["no output"])[-1]
        return dict(base, passed=False, kinds=["error"], reasons=[f"mobb exit {p.returncode}: {err}"])
    try:
        return dict(base, **judge(record, scenario, p.stdout))
    except (OSError, ValueError, KeyError) as e:
        return dict(base, passed=False, kinds=["error"], reasons=[f"cannot judge the record: {e}"])


def scenario_files(paths):
    out = []
    for p in paths:
        if os.path.isdir(p):
            files = sorted(glob.glob(os.path.join(p, "*.json")))
            out += [(os.path.basename(os.path.normpath(p)), f) for f in files]
        else:
            out.append((os.path.basename(os.path.dirname(os.path.abspath(p))), p))
    return out


def fmt(v, spec, none="-"):
    return none if v is None else format(v, spec)


def main():
    parser = argparse.ArgumentParser(description="Run crowd scenarios and judge each run from its record.",
                                     epilog=__doc__.split("\n\n", 2)[2], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("paths", nargs="*", default=[os.path.join(ROOT, "assets", "scenarios")],
                        help="scenario folders (their *.json) or files (default assets/scenarios)")
    parser.add_argument("--mobb", default=os.path.join(ROOT, "build", "src", "app", "mobb"), help="the mobb binary")
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3], help="seeds (default 1 2 3)")
    parser.add_argument("--out", help="keep the records in this folder (default: a temporary one)")
    parser.add_argument("--jobs", type=int, default=2, help="runs at a time (default 2)")
    parser.add_argument("--json", action="store_true", help="print JSON instead of the table")
    args = parser.parse_args()
    mobb = os.path.abspath(args.mobb)
    if not os.access(mobb, os.X_OK):
        parser.error(f"no mobb binary at {mobb}")
    files = scenario_files(args.paths)
    if not files:
        parser.error("no scenario files")
    with tempfile.TemporaryDirectory(prefix="judge_scenarios_") as tmp:
        out = args.out or tmp
        os.makedirs(out, exist_ok=True)
        tasks = []
        for label, f in files:
            name = os.path.splitext(os.path.basename(f))[0]
            for seed in args.seeds:
                tasks.append((mobb, f, seed, os.path.join(out, f"{label}__{name}__seed{seed}.json"), label))
        t0 = time.perf_counter()
        with concurrent.futures.ProcessPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            results = list(pool.map(run_one, tasks))
        total_wall = time.perf_counter() - t0
    passed = sum(r["passed"] for r in results)
    sets = {}
    for r in results:
        s = sets.setdefault(r["label"], [0, 0])
        s[0] += r["passed"]
        s[1] += 1
    if args.json:
        json.dump({"mobb": mobb, "seeds": args.seeds, "runs": results, "passed": passed, "total": len(results),
                   "sets": {k: {"passed": v[0], "total": v[1]} for k, v in sets.items()},
                   "wall": total_wall}, sys.stdout, indent=1)
        print()
        return
    sources = sorted({r.get("speed_source") for r in results if r.get("speed_source")})
    speeds = sorted({round(r["graph_speed"], 4) for r in results if r.get("graph_speed")})
    print(f"mobb {mobb}; seeds {' '.join(map(str, args.seeds))}; t0 = straight distance / graph mean clip speed "
          f"{', '.join(map(str, speeds)) or '-'} m/s (from {', '.join(sources) or '-'}); "
          f"idle: < {IDLE_SPEED} m/s over {IDLE_WINDOW} s, at-goal time excluded")
    width = max(len(f"{r['label']}/{os.path.splitext(os.path.basename(r['file']))[0]}") for r in results)
    print(f"{'scenario':<{width}}  seed  result  goal ok  reached   t/t0  idle%  wall s  reason")
    for r in results:
        name = f"{r['label']}/{os.path.splitext(os.path.basename(r['file']))[0]}"
        ok = f"{r['goal_ok']}/{r['goal_agents']}" if "goal_ok" in r else "-"
        reached = f"{r['reached']}/{r['goal_agents']}" if "reached" in r else "-"
        idle = fmt(100 * r["idle_share"], ".1f") if "idle_share" in r else "-"
        print(f"{name:<{width}}  {r['seed']:>4}  {'pass' if r['passed'] else 'FAIL':<6}  {ok:>7}  {reached:>7}  "
              f"{fmt(r.get('time_ratio'), '5.2f'):>5}  {idle:>5}  {r['wall']:6.2f}  {' | '.join(r['reasons'])}")
    for label, (p, t) in sets.items():
        print(f"{label}: {p} of {t} runs pass")
    counts = {}
    for r in results:
        for k in r.get("kinds", []):
            counts[k] = counts.get(k, 0) + 1
    names = {"contact": "agents' disks overlapping", "solid": "a disk on a wall or obstacle", "never": "an agent never within 1 m",
             "late": "an agent first within 1 m after its deadline", "error": "mobb or the record failed",
             "left": "an agent within 1 m in time but out of the circle later"}
    if counts:
        print("failed runs by reason (a run may have several): " +
              ", ".join(f"{names.get(k, k)} {v}" for k, v in sorted(counts.items(), key=lambda kv: -kv[1])))
    print(f"{passed} of {len(results)} runs pass ({total_wall:.0f} s wall)")


if __name__ == "__main__":
    main()
