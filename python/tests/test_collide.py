"""mobb.collide with counters against `mobb query`, the trace, and clearance against collide."""
import json
import math
import os

import numpy as np
import pytest

import mobb
from conftest import run_cli

# (x, y, theta in degrees, t0) pairs: head-on, side by side, apart in time, crossing
PLACEMENTS = [((0, 0, 0, 0), (3, 0, 180, 0)), ((0, 0, 0, 0), (0, 1.5, 0, 0.2)),
              ((0, 0, 0, 0), (1, 0, 90, 5)), ((-1, -1, 45, 0), (1, -1, 135, 0.5))]


def rad(p):
    return (p[0], p[1], p[2] * (math.pi / 180.0), p[3])


@pytest.fixture(scope="module")
def walks(data):
    return os.path.join(data, "cmu", "002_01.bvh"), os.path.join(data, "cmu", "002_02.bvh")


@pytest.mark.parametrize("tree", ["mobb", "umobb", "hybrid2"])
def test_counters_equal_mobb_query(walks, mobb_exe, tree):
    a, b = walks
    ta, tb = mobb.Tree(mobb.load(a), type=tree), mobb.Tree(mobb.load(b), type=tree)
    outcomes = set()
    for pa, pb in PLACEMENTS:
        code, out, err = run_cli(mobb_exe, "query", a, b, "--tree", tree, "--place-a", ",".join(map(str, pa)),
                                 "--place-b", ",".join(map(str, pb)))
        assert code == 0, err
        expected = json.loads(out)
        got = mobb.collide(ta, rad(pa), tb, rad(pb), counters=True)
        assert {k: got[k] for k in expected} == expected
        assert mobb.collide(ta, rad(pa), tb, rad(pb)) is expected["collide"]
        outcomes.add(expected["collide"])
    assert outcomes == {True, False}


def test_trace(walks):
    ca, cb = (mobb.load(f) for f in walks)
    ta, tb = mobb.Tree(ca), mobb.Tree(cb)
    for pa, pb in PLACEMENTS:
        r = mobb.collide(ta, rad(pa), tb, rad(pb), trace=True)
        events = r["trace"]
        assert all(e["test"] in ("time", "box2d", "box3d", "descend", "samples") for e in events)
        hits = [e for e in events if e["outcome"] == "hit"]
        if r["collide"]:
            # the query stops at its first hit: the last event, naming the pair it returns
            assert hits == [events[-1]]
            assert (hits[0]["sample_a"], hits[0]["sample_b"]) == r["pair"]
        else:
            assert hits == [] and r["pair"] is None
        assert sum(e["samples_tested"] for e in events) == r["samples"]


def test_brute_counters_and_sweep(walks):
    ca, cb = (mobb.load(f) for f in walks)
    ia, ib = mobb.ClipIndex(ca), mobb.ClipIndex(cb)
    for pa, pb in PLACEMENTS:
        brute = mobb.collide(ca, rad(pa), cb, rad(pb), counters=True)
        assert brute["tests2d"] == 0 and brute["tests3d"] == 0
        assert mobb.collide(ia, rad(pa), ib, rad(pb)) == brute["collide"]
    with pytest.raises(ValueError, match="trees"):
        mobb.collide(ia, rad(pa), ib, rad(pb), counters=True)
    with pytest.raises(ValueError, match="trees"):
        mobb.collide(ca, rad(pa), cb, rad(pb), trace=True)


def test_clearance_negative_exactly_when_colliding(walks):
    ca, cb = (mobb.load(f) for f in walks)
    for pa, pb in PLACEMENTS:
        c = mobb.clearance(ca, rad(pa), cb, rad(pb))
        assert c["t"].shape == c["gap"].shape == c["i"].shape == c["j"].shape
        assert bool((c["gap"] < 0).any()) == mobb.collide(ca, rad(pa), cb, rad(pb))
        # t is the global start time of sample i of a
        np.testing.assert_allclose(c["t"], rad(pa)[3] + c["i"] * ca.dt)


def test_tree_from_array(walks):
    clip = mobb.load(walks[0])
    from_clip, from_array = mobb.Tree(clip), mobb.Tree(clip.path)
    assert from_array.dt == pytest.approx(clip.dt)
    assert (from_clip.nodes, from_clip.depth, len(from_clip)) == (from_array.nodes, from_array.depth, len(clip))
    np.testing.assert_array_equal(from_clip.path, clip.path)
