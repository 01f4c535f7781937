"""mobb_dask.collide_batch on a local Dask cluster of two worker processes against mobb.collide_batch in
one process, on generated walks (no mocap needed); and the trees' pickles, which carry them to workers."""
import math
import pickle

import numpy as np
import pytest

import mobb

try:
    import dask.array as da
    from distributed import Client, LocalCluster, get_task_stream
except ImportError as e:  # Debian's python3-dask and python3-distributed (scripts/install-deps)
    pytest.skip(f"dask or distributed not importable ({e})", allow_module_level=True)

import mobb_dask

COUNT = 20_000
BLOCK = 2_500  # 8 blocks: both workers get some


def walk(samples, speed, turn):
    """(n, 4) rows t, x, y, r of a walk at `speed` m/s bending `turn` rad/s, radius 0.25 m, 60 Hz."""
    dt = 1 / 60
    t = np.arange(samples) * dt
    heading = turn * t
    x = np.cumsum(speed * np.cos(heading) * dt)
    y = np.cumsum(speed * np.sin(heading) * dt)
    return np.column_stack([t, x, y, np.full(samples, 0.25)])


def placements(rng, count):
    """(count, 4) rows x, y (m), theta (rad), t0 (s): within a metre and a second of each other, so that
    some pairs meet and some do not."""
    return np.column_stack([rng.uniform(-1, 1, count), rng.uniform(-1, 1, count),
                            rng.uniform(-math.pi, math.pi, count), rng.uniform(-1, 1, count)])


@pytest.fixture(scope="module")
def workload():
    rng = np.random.default_rng(46)
    ta = mobb.Tree(walk(180, 1.3, 0.4))
    tb = mobb.Tree(walk(150, 1.1, -0.6), type="umobb", n_min=4)
    pa, pb = placements(rng, COUNT), placements(rng, COUNT)
    expected = mobb.collide_batch(ta, tb, pa, pb, threads=1)
    assert 0.1 < expected.mean() < 0.9, expected.mean()  # a wrong answer cannot hide
    return ta, tb, pa, pb, expected


@pytest.fixture(scope="module")
def client():
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as c:
        c.wait_for_workers(2)
        yield c


def test_trees_pickle_as_their_path_and_options(workload):
    ta, tb, pa, pb, expected = workload
    for t in (ta, tb):
        copy = pickle.loads(pickle.dumps(t))
        assert (copy.type, copy.n_min, copy.nodes, copy.depth, copy.dt) == (t.type, t.n_min, t.nodes, t.depth, t.dt)
        np.testing.assert_array_equal(copy.path, t.path)
    ia = pickle.loads(pickle.dumps(mobb.ClipIndex(ta)))
    assert ia.levels == mobb.ClipIndex(ta).levels
    copies = pickle.loads(pickle.dumps((ta, tb)))
    np.testing.assert_array_equal(mobb.collide_batch(*copies, pa, pb), expected)


def test_local_threads_and_bad_shapes(workload):
    ta, tb, pa, pb, expected = workload
    hits = mobb_dask.collide_batch(ta, tb, da.from_array(pa, chunks=(7_000, 2)), da.from_array(pb, chunks=3_000))
    np.testing.assert_array_equal(hits.compute(scheduler="threads"), expected)
    with pytest.raises(ValueError, match="placements_b: 20000 and 10 rows"):
        mobb_dask.collide_batch(ta, tb, pa, pb[:10])
    with pytest.raises(ValueError, match=r"placements_a: expected a \(k, 4\) array"):
        mobb_dask.collide_batch(ta, tb, pa[:, :3], pb)


def test_two_workers_answer_as_one_process(workload, client):
    ta, tb, pa, pb, expected = workload
    hits = mobb_dask.collide_batch(ta, tb, da.from_array(pa, chunks=(BLOCK, 4)), pb)
    assert hits.shape == (COUNT,) and hits.numblocks == (COUNT // BLOCK,)
    with get_task_stream(client) as stream:
        out = hits.compute()
    assert out.dtype == np.bool_
    np.testing.assert_array_equal(out, expected)
    workers = {t["worker"] for t in stream.data if "mobb-collide-batch" in str(t["key"])}
    assert len(workers) == 2, workers  # the blocks were shared out


def test_circle_indexes_and_numpy_input_on_the_cluster(workload, client):
    ta, tb, pa, pb, expected = workload
    ia, ib = mobb.ClipIndex(ta), mobb.ClipIndex(tb)
    out = mobb_dask.collide_batch(ia, ib, pa, pb, block_rows=3_000).compute()
    np.testing.assert_array_equal(out, expected)
