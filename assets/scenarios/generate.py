#!/usr/bin/env python3
"""Writes the shipped crowd scenarios (README.md in this folder): python3 assets/scenarios/generate.py

Each is modelled on one of SteerSuite's public test cases (SteerSuite/Release, testcases/*.xml), in mobb's
frame: SteerSuite's ground (x, z) is mobb's (x, y). Geometry, starts and goals follow the test case; crowds
are smaller where SteerSuite's run to hundreds of agents, at about the same density. Starts keep the room
mobb's agents need to stop where they stand (held ground of about 0.5 m, 0.92 m from walls), and each agent
of a group has a goal of its own (two agents cannot stand on one point). Random layouts come from a fixed
seed, so the files are the same on every run."""
import json
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
CLEAR = 1.0   # metres from walls and obstacles to a start or a goal
APART = 1.4   # metres between starts, and between goals


def agent(start, goal, heading=None, start_time=None):
    a = {"start": [round(start[0], 2), round(start[1], 2)]}
    if heading is not None:
        a["heading"] = round(heading, 1)
    if start_time:
        a["start_time"] = start_time
    a["goal"] = [round(goal[0], 2), round(goal[1], 2)]
    return a


def write(name, source, description, world, time_limit, agents, obstacles=()):
    scenario = {"name": name, "description": description, "source": source, "world": world, "walls": True,
                "obstacles": [{"rectangle": list(o)} for o in obstacles], "time_limit": time_limit, "agents": agents}
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        json.dump(scenario, f, indent=2)
        f.write("\n")


def box_distance(p, box):
    dx = max(box[0] - p[0], 0, p[0] - box[2])
    dy = max(box[1] - p[1], 0, p[1] - box[3])
    return math.hypot(dx, dy)


def clear_of(p, world, obstacles):
    inside = world[0] + CLEAR <= p[0] <= world[2] - CLEAR and world[1] + CLEAR <= p[1] <= world[3] - CLEAR
    return inside and all(box_distance(p, o) >= CLEAR for o in obstacles)


def scatter(rng, count, region, world, obstacles, taken=()):
    """`count` points uniform in region [x0, y0, x1, y1], clear of walls and obstacles, APART from each other."""
    out = list(taken)
    while len(out) < len(taken) + count:
        p = (round(rng.uniform(region[0], region[2]), 2), round(rng.uniform(region[1], region[3]), 2))
        if clear_of(p, world, obstacles) and all(math.dist(p, q) >= APART for q in out):
            out.append(p)
    return out[len(taken):]


def far_first(starts, goals, entry, exit_):
    """Pairs the starts nearest the way in with the goals farthest from it, so early arrivals do not stand
    in the way of later ones (an agent at its goal keeps standing there)."""
    by_start = sorted(starts, key=lambda p: math.dist(p, entry))
    by_goal = sorted(goals, key=lambda p: -math.dist(p, exit_))
    return list(zip(by_start, by_goal))


def grid(x0, x1, y0, y1, columns, rows):
    xs = [x0 + (x1 - x0) * k / max(1, columns - 1) for k in range(columns)]
    ys = [y0 + (y1 - y0) * k / max(1, rows - 1) for k in range(rows)]
    return [(x, y) for x in xs for y in ys]


def main():
    square = [-12, -12, 12, 12]
    write("oncoming", "SteerSuite testcases/oncoming-1.xml",
          "Two agents walk head-on along almost the same line and must pass each other.", square, 40,
          [agent((-1, -10), (0, 10)), agent((-1, 10), (0, -10))])
    write("crossing", "SteerSuite testcases/crossing-1.xml",
          "Two agents cross at right angles, reaching the crossing about a second apart.", square, 40,
          [agent((9, 1), (-10, 1)), agent((1, 10), (1, -10))])
    write("four_way", "SteerSuite testcases/4-way-confusion.xml",
          "Four agents from the four sides meet in the middle at the same time.", square, 45,
          [agent((-1, -10.1), (0, 10)), agent((-1, 10.1), (0, -10)), agent((-10, -1), (10, 0)),
           agent((10, -1), (-10, 0))])

    rng = random.Random(20261122)
    hall = [-30, -8, 30, 8]
    starts = scatter(rng, 40, [-27, -7, 20, 7], hall, [])
    east = far_first(starts[:20], grid(20, 29, -6, 6, 4, 5), (30, 0), (19, 0))
    west = far_first(starts[20:], grid(-29, -20, -6, 6, 4, 5), (-30, 0), (-19, 0))
    write("hallway_two_way", "SteerSuite testcases/hallway-two-way.xml",
          "A 16 m wide hallway: 20 agents walk east and 20 west, starting mixed in the same stretch.", hall, 120,
          [agent(s, g, 0) for s, g in east] + [agent(s, g, 180) for s, g in west])

    door = [-16, -1, 16, 3.1]
    posts = [(-0.2, -1, 0, -0.3), (-0.2, 1.3, 0, 3.1)]
    write("doorway_two_way", "SteerSuite testcases/doorway-two-way.xml",
          "A 4.1 m corridor cut by a wall with a 1.6 m door: two agents cross it from both sides, one must wait.",
          door, 60, [agent((-10, 1), (14, 1)), agent((10, 1), (-14, 1))], posts)

    circle = []
    for k in range(20):
        phi = math.radians(18 * k)
        start = (10 * math.cos(phi), 10 * math.sin(phi))
        circle.append(agent(start, (-start[0], -start[1])))
    write("circle_20", "SteerSuite testcases/circle-20.xml (goals at the antipodes, one speed: mobb's clips)",
          "Twenty agents on a circle of 10 m each walk to the opposite point: all meet in the middle.", square, 90,
          circle)

    neck = [-32, -15, 45, 15]
    walls = [(-11, 2.1, 20, 15), (-11, -15, 20, -2.1)]
    rng = random.Random(7)
    starts = scatter(rng, 30, [23, -10, 43, 10], neck, walls)
    pairs = far_first(starts, grid(-30, -15, -12, 12, 4, 8), (20, 0), (-11, 0))
    write("bottleneck", "SteerSuite testcases/bottleneck-squeeze.xml (30 agents instead of 1,000)",
          "Thirty agents in an open field squeeze through a 31 m long, 4.2 m wide corridor to the far side.", neck, 180,
          [agent(s, g, rng.uniform(-180, 180)) for s, g in pairs], walls)

    field = [-20, -20, 20, 20]
    rng = random.Random(20240601)
    blocks = []
    while len(blocks) < 24:
        c = (round(rng.uniform(-16, 16), 1), round(rng.uniform(-16, 16), 1))
        if all(max(abs(c[0] - a), abs(c[1] - b)) - 1.0 >= 2.5 for a, b in blocks):
            blocks.append(c)
    obstacles = [(a - 0.5, b - 0.5, a + 0.5, b + 0.5) for a, b in blocks]
    starts, goals = [], []
    while len(starts) < 24:
        s = scatter(rng, 1, [-18, -18, 18, 18], field, obstacles, starts)[0]
        for _ in range(500):
            g = scatter(rng, 1, [-18, -18, 18, 18], field, obstacles, goals)[0]
            if math.dist(s, g) >= 15:
                starts.append(s)
                goals.append(g)
                break
    write("random_obstacles", "SteerSuite testcases/forest.xml and random.xml (24 agents, 24 pillars of 1 m)",
          "Twenty-four agents cross a walled 40 m square among 24 square pillars, each to its own goal.", field, 90,
          [agent(s, g) for s, g in zip(starts, goals)], obstacles)


if __name__ == "__main__":
    main()
