"""mobb.collide_batch against `mobb batch` on 10,000 placements of real clips, and every method and
thread count against each other."""
import json
import math
import os

import numpy as np
import pytest

import mobb
from conftest import run_cli

COUNT = 10_000


def placements(rng, count):
    """(count, 4) rows x, y (m), theta (degrees, as the command line takes it), t0 (s): two walks placed
    within a metre and a second of each other, so that some meet and some do not."""
    return np.column_stack([rng.uniform(-1, 1, count), rng.uniform(-1, 1, count),
                            rng.uniform(-180, 180, count), rng.uniform(-1, 1, count)])


def radians(deg):
    """The library's conversion (core/angle.h): degrees * (pi / 180), so both sides get the same bits."""
    out = deg.copy()
    out[:, 2] = deg[:, 2] * (math.pi / 180.0)
    return out


@pytest.fixture(scope="module")
def workload(data):
    rng = np.random.default_rng(13)
    a, b = os.path.join(data, "cmu", "002_01.bvh"), os.path.join(data, "cmu", "005_01.bvh")
    return a, b, placements(rng, COUNT), placements(rng, COUNT)


def test_collide_batch_equals_mobb_batch(workload, mobb_exe):
    a, b, pa, pb = workload
    lines = "".join(json.dumps({"a": a, "b": b, "ta": list(ra), "tb": list(rb)}) + "\n" for ra, rb in zip(pa, pb))
    code, out, err = run_cli(mobb_exe, "batch", stdin=lines)
    assert code == 0, err
    expected = np.array([json.loads(line)["collide"] for line in out.splitlines()])
    assert expected.shape == (COUNT,)

    hits = mobb.collide_batch(mobb.Tree(mobb.load(a)), mobb.Tree(mobb.load(b)), radians(pa), radians(pb))
    assert hits.dtype == np.bool_ and hits.shape == (COUNT,)
    np.testing.assert_array_equal(hits, expected)
    # a workload that can tell right from wrong answers: both outcomes well represented
    assert 0.1 < expected.mean() < 0.9, expected.mean()


def test_methods_and_threads_agree(workload):
    a, b, pa, pb = workload
    ca, cb = mobb.load(a), mobb.load(b)
    ra, rb = radians(pa), radians(pb)
    reference = mobb.collide_batch(ca, cb, ra, rb, threads=1)  # brute force
    for x, y in [(mobb.Tree(ca, type="umobb", n_min=4), mobb.Tree(cb, type="hybrid1")),
                 (mobb.ClipIndex(ca), mobb.ClipIndex(cb))]:
        for threads in (1, 3):
            np.testing.assert_array_equal(mobb.collide_batch(x, y, ra, rb, threads=threads), reference)
    # one pair at a time gives the batch's answers
    ta, tb = mobb.Tree(ca), mobb.Tree(cb)
    for k in range(0, COUNT, 97):
        assert mobb.collide(ta, ra[k], tb, rb[k]) == reference[k]


def test_empty_batch(workload):
    a, b, _, _ = workload
    t = mobb.Tree(mobb.load(a))
    out = mobb.collide_batch(t, t, np.zeros((0, 4)), np.zeros((0, 4)))
    assert out.shape == (0,) and out.dtype == np.bool_
