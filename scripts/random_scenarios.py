#!/usr/bin/env python3
"""Random crowd scenarios for `mobb crowd --scenario` (issue 28), seeded, valid by construction.

    scripts/random_scenarios.py OUT_DIR [-n 10] [--seed 1] [--kinds obstacles,open,door,corridor]

Writes OUT_DIR/random_SSSS_KK_KIND.json (S the seed, K the index), cycling through the kinds:
  obstacles  a walled room with random rectangular obstacles, agents with random starts and goals
  open       a walled room, agents with random starts and goals
  door       a room cut in two by a wall with one door; agents on both sides, each to a goal on the other
  corridor   a corridor (the world itself, 3.5 to 8 m wide); agents from both ends to the far end
and, only when --kinds names them (the default cycle, and so the sets of earlier measurements, stay as they
were):
  fan_in     agents on an arc 9 to 13 m out, each to a random goal of a block of goals 1.5 m apart
  fan_out    the same the other way: from the block out to the arc
  ring       agents standing for good on a ring 3.5 to 5 m across with three gaps, crossed by walkers

In the door and corridor kinds the agents of a side that will come through first get the farthest goals
(as the shipped hallway and bottleneck). Every scenario keeps the rules of assets/scenarios/generate.py: starts and goals 1.0 m or more from walls and
obstacles, starts 1.4 m or more apart, goals 1.4 m or more apart (all of them, not only a group's). Each
goal is reachable from its start: on a grid of 0.25 m cells, those whose centre is 0.6 m or more from every
wall and obstacle, 4-connected, the start's cell reaches the goal's (breadth-first search). The time limit
is the largest over agents of 3 x (grid path length) / 1.3 m/s + 20 s, rounded up to 10 s. Pure Python.
"""
import argparse
import json
import math
import os
import random
from collections import deque

CLEAR = 1.0    # metres from walls and obstacles to a start or a goal
APART = 1.4    # metres between starts, and between goals
PASS = 0.6     # metres from walls and obstacles to a cell centre an agent may walk through
CELL = 0.25    # metres: the reachability grid
KINDS = ("obstacles", "open", "door", "corridor")


def box_distance(p, box):
    dx = max(box[0] - p[0], 0, p[0] - box[2])
    dy = max(box[1] - p[1], 0, p[1] - box[3])
    return math.hypot(dx, dy)


def clearance(p, world, boxes):
    """Distance from p to the nearest wall (world edge) or obstacle; negative outside the world."""
    d = min(p[0] - world[0], world[2] - p[0], p[1] - world[1], world[3] - p[1])
    for b in boxes:
        d = min(d, box_distance(p, b))
    return d


class Grid:
    """Cells of CELL metres over the world, free when their centre is PASS or more from every solid."""

    def __init__(self, world, boxes):
        self.world = world
        self.nx = int(math.ceil((world[2] - world[0]) / CELL))
        self.ny = int(math.ceil((world[3] - world[1]) / CELL))
        self.free = [[clearance(self.centre(i, j), world, boxes) >= PASS for j in range(self.ny)]
                     for i in range(self.nx)]

    def centre(self, i, j):
        return (self.world[0] + (i + 0.5) * CELL, self.world[1] + (j + 0.5) * CELL)

    def cell(self, p):
        i = min(self.nx - 1, max(0, int((p[0] - self.world[0]) / CELL)))
        j = min(self.ny - 1, max(0, int((p[1] - self.world[1]) / CELL)))
        return i, j

    def path_length(self, a, b):
        """Metres along the 4-connected free cells from a's cell to b's, or None when b is out of reach."""
        start, goal = self.cell(a), self.cell(b)
        if not self.free[start[0]][start[1]] or not self.free[goal[0]][goal[1]]:
            return None
        steps = {start: 0}
        queue = deque([start])
        while queue:
            c = queue.popleft()
            if c == goal:
                return steps[c] * CELL
            for n in ((c[0] + 1, c[1]), (c[0] - 1, c[1]), (c[0], c[1] + 1), (c[0], c[1] - 1)):
                if 0 <= n[0] < self.nx and 0 <= n[1] < self.ny and self.free[n[0]][n[1]] and n not in steps:
                    steps[n] = steps[c] + 1
                    queue.append(n)
        return None


def point(rng, region, world, boxes, taken, tries=2000):
    """A point uniform in region [x0, y0, x1, y1], CLEAR of every solid and APART from `taken`, or None."""
    for _ in range(tries):
        p = (round(rng.uniform(region[0], region[2]), 2), round(rng.uniform(region[1], region[3]), 2))
        if clearance(p, world, boxes) >= CLEAR and all(math.dist(p, q) >= APART for q in taken):
            return p
    return None


def pick_agents(rng, count, world, boxes, start_region, goal_region, min_distance):
    """Up to `count` (start, goal) pairs: start in start_region(rng), goal in goal_region(rng, start), both
    valid, the goal min_distance or more from the start."""
    starts, goals = [], []
    for _ in range(count * 20):
        if len(starts) == count:
            break
        s = point(rng, start_region(rng), world, boxes, starts, 200)
        if s is None:
            continue
        g = point(rng, goal_region(rng, s), world, boxes, goals, 200)
        if g is None or math.dist(s, g) < min_distance:
            continue
        starts.append(s)
        goals.append(g)
    return list(zip(starts, goals))


def far_first(pairs, side, entry, exit_):
    """Re-pairs the starts and goals of each side (side(start) names it): the starts nearest the way in
    (entry(side)) take the goals farthest from the way out (exit_(side)), so that early arrivals, who stand
    at their goals for good, do not stand in the way of later ones (as assets/scenarios/generate.py)."""
    out = []
    for name in sorted({side(s) for s, _ in pairs}):
        group = [(s, g) for s, g in pairs if side(s) == name]
        starts = sorted((s for s, _ in group), key=lambda p: math.dist(p, entry(name)))
        goals = sorted((g for _, g in group), key=lambda p: -math.dist(p, exit_(name)))
        out += list(zip(starts, goals))
    return out


def rectangles(rng, count, world, keep_out=2.0):
    """Up to `count` random rectangles inside the world, keep_out metres from its walls and from each other."""
    boxes = []
    for _ in range(count * 50):
        if len(boxes) == count:
            break
        w, h = rng.uniform(0.5, 4.0), rng.uniform(0.5, 4.0)
        x = rng.uniform(world[0] + keep_out, world[2] - keep_out - w)
        y = rng.uniform(world[1] + keep_out, world[3] - keep_out - h)
        b = tuple(round(v, 2) for v in (x, y, x + w, y + h))
        if all(b[0] - o[2] >= keep_out or o[0] - b[2] >= keep_out or b[1] - o[3] >= keep_out or
               o[1] - b[3] >= keep_out for o in boxes):
            boxes.append(b)
    return boxes


def room(rng):
    w, h = rng.randint(20, 40), rng.randint(20, 40)
    return [-w / 2, -h / 2, w / 2, h / 2]


def scenario_obstacles(rng):
    world = room(rng)
    boxes = rectangles(rng, rng.randint(4, 16), world)
    n = rng.randint(8, 30)
    anywhere = lambda *_: world
    agents = pick_agents(rng, n, world, boxes, anywhere, anywhere, 8)
    return world, boxes, agents, f"A walled {world[2] - world[0]:g} x {world[3] - world[1]:g} m room with {len(boxes)} " \
        f"random rectangular obstacles; {len(agents)} agents with random starts and goals."


def scenario_open(rng):
    world = room(rng)
    n = rng.randint(10, 40)
    anywhere = lambda *_: world
    agents = pick_agents(rng, n, world, [], anywhere, anywhere, 8)
    return world, [], agents, f"A walled {world[2] - world[0]:g} x {world[3] - world[1]:g} m room; {len(agents)} agents " \
        "with random starts and goals."


def scenario_door(rng):
    world = room(rng)
    thick = round(rng.uniform(0.2, 1.0), 2)
    x = round(rng.uniform(world[0] + 6, world[2] - 6 - thick), 2)
    door = round(rng.uniform(1.6, 3.0), 2)
    y = round(rng.uniform(world[1] + 1, world[3] - 1 - door), 2)
    boxes = [b for b in ((x, world[1], x + thick, y), (x, y + door, x + thick, world[3])) if b[3] - b[1] > 0.05]
    west, east = [world[0], world[1], x, world[3]], [x + thick, world[1], world[2], world[3]]
    n = rng.randint(4, 24)
    other = lambda rng_, s: east if s[0] < x else west
    agents = pick_agents(rng, n, world, boxes, lambda r: west if r.random() < 0.5 else east, other, 4)
    gap = (x + thick / 2, y + door / 2)
    agents = far_first(agents, lambda s: s[0] < x, lambda _: gap, lambda _: gap)
    return world, boxes, agents, f"A walled {world[2] - world[0]:g} x {world[3] - world[1]:g} m room cut by a " \
        f"{thick:g} m wall with a {door:g} m door; {len(agents)} agents on both sides, each to the other side."


def scenario_corridor(rng):
    length, width = rng.randint(30, 60), round(rng.uniform(3.5, 8), 1)
    world = [-length / 2, -width / 2, length / 2, width / 2]
    n = rng.randint(4, 24)
    west = [world[0], world[1], world[0] + length / 3, world[3]]
    east = [world[2] - length / 3, world[1], world[2], world[3]]
    other = lambda rng_, s: east if s[0] < 0 else west
    agents = pick_agents(rng, n, world, [], lambda r: west if r.random() < 0.5 else east, other, length / 3)
    ends = {True: (world[2], 0), False: (world[0], 0)}  # west starters walk to the east end, and back
    middle = lambda west_side: (world[2] - length / 3, 0) if west_side else (world[0] + length / 3, 0)
    agents = far_first(agents, lambda s: s[0] < 0, lambda w: ends[w], middle)
    return world, [], agents, f"A {length:g} m corridor {width:g} m wide; {len(agents)} agents from both ends, each " \
        "to the far end."


def fan(rng):
    """A block of goals (three columns 1.5 m apart) right of the room's centre and an arc of starts round it
    on the left, APART along the arc; the goals dealt at random."""
    world = [-16, -16, 16, 16]
    n, radius = rng.randint(8, 14), round(rng.uniform(9, 13), 2)
    spread = max(math.radians(rng.uniform(60, 120)), APART * 1.1 * (n - 1) / radius)
    block = [(3 + 1.5 * (k % 3), -3 + 1.5 * (k // 3)) for k in range(n)]
    arc = [(round(radius * math.cos(a), 2), round(radius * math.sin(a), 2))
           for a in (math.pi - spread / 2 + spread * k / (n - 1) for k in range(n))]
    rng.shuffle(block)
    return world, n, radius, list(zip(arc, block))


def scenario_fan_in(rng):
    world, n, radius, pairs = fan(rng)
    return world, [], pairs, f"A walled 32 x 32 m room; {n} agents on an arc {radius:g} m out, each to a random " \
        "goal of a block of goals 1.5 m apart (a fan-in)."


def scenario_fan_out(rng):
    world, n, radius, pairs = fan(rng)
    return world, [], [(g, s) for s, g in pairs], f"A walled 32 x 32 m room; {n} agents from a block 1.5 m apart, " \
        f"each to a random place on an arc {radius:g} m out (a fan-out)."


def scenario_ring(rng):
    world = [-15, -15, 15, 15]
    m, radius = rng.randint(8, 12), rng.uniform(3.5, 5.0)
    gaps = set(rng.sample(range(m), 3))
    ring = [(round(radius * math.cos(2 * math.pi * k / m), 2), round(radius * math.sin(2 * math.pi * k / m), 2))
            for k in range(m) if k not in gaps]
    walkers = []
    for _ in range(rng.randint(6, 10)):
        a = rng.uniform(0, 2 * math.pi)
        b = a + math.pi + rng.uniform(-0.5, 0.5)
        s, g = [(round(12 * math.cos(t), 2), round(12 * math.sin(t), 2)) for t in (a, b)]
        if all(math.dist(s, w[0]) >= APART and math.dist(g, w[1]) >= APART for w in walkers):
            walkers.append((s, g))
    return world, [], [(p, p) for p in ring] + walkers, f"A walled 30 x 30 m room; {len(ring)} agents standing for " \
        f"good on a ring {2 * radius:.1f} m across with three gaps, {len(walkers)} walkers crossing the room through it."


MAKERS = {"obstacles": scenario_obstacles, "open": scenario_open, "door": scenario_door, "corridor": scenario_corridor,
          "fan_in": scenario_fan_in, "fan_out": scenario_fan_out, "ring": scenario_ring}


def make(kind, seed):
    """One valid scenario of `kind` from `seed` (draws again until every agent's goal is reachable)."""
    rng = random.Random(f"{kind}:{seed}")
    while True:
        world, boxes, pairs, description = MAKERS[kind](rng)
        if len(pairs) < 2:
            continue
        grid = Grid(world, boxes)
        lengths = [grid.path_length(s, g) for s, g in pairs]
        if any(length is None for length in lengths):
            continue
        limit = max(3 * length / 1.3 + 20 for length in lengths)
        return {"name": None, "description": description, "source": None, "world": world, "walls": True,
                "obstacles": [{"rectangle": list(b)} for b in boxes],
                "time_limit": int(math.ceil(limit / 10) * 10),
                "agents": [{"start": list(s), "goal": list(g)} for s, g in pairs]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", help="folder to write the scenarios to (made if missing)")
    parser.add_argument("-n", type=int, default=10, help="how many (default 10)")
    parser.add_argument("--seed", type=int, default=1, help="base seed (default 1)")
    parser.add_argument("--kinds", default=",".join(KINDS),
                        help=f"comma-separated, cycled (default {','.join(KINDS)}; also {','.join(sorted(set(MAKERS) - set(KINDS)))})")
    args = parser.parse_args()
    kinds = [k for k in args.kinds.split(",") if k]
    for k in kinds:
        if k not in MAKERS:
            parser.error(f"unknown kind {k!r} (kinds: {', '.join(MAKERS)})")
    os.makedirs(args.out, exist_ok=True)
    for i in range(args.n):
        kind = kinds[i % len(kinds)]
        s = make(kind, args.seed * 1000 + i)
        name = f"random_{args.seed:04d}_{i:02d}_{kind}"
        s["name"] = name
        s["source"] = f"scripts/random_scenarios.py --seed {args.seed} (scenario {i}, kind {kind})"
        path = os.path.join(args.out, name + ".json")
        with open(path, "w") as f:
            json.dump(s, f, indent=2)
            f.write("\n")
        print(f"{path}: {len(s['agents'])} agents, {len(s['obstacles'])} obstacles, {s['time_limit']} s")


if __name__ == "__main__":
    main()
