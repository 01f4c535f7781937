"""mobb.collide_batch over Dask arrays of placements: a machine's cores, or a Dask cluster's workers.

Batch queries need no order, so the (k, 4) placements split into blocks of rows that any worker answers
alone (Dask: https://docs.dask.org; Debian's python3-dask and python3-distributed). The pair of trees is
one key of the task graph that every block's task depends on: Dask builds it where it first runs and
copies it once to each other worker that answers a block, which keeps it for all its blocks. A copy is
built again from the clip's path and options (mobb.Tree and mobb.ClipIndex pickle so), so each worker
builds each tree once and no tree's nodes travel.

    import dask.array as da, mobb, mobb_dask
    from distributed import Client
    client = Client("scheduler:8786")      # or none: Dask's threads on this machine
    pa = da.from_array(placements_a, chunks=(100_000, 4))
    hits = mobb_dask.collide_batch(ta, tb, pa, placements_b).compute()   # (k,) bools

The answers are mobb.collide_batch(ta, tb, placements_a, placements_b)'s, whatever the blocks and workers.
"""

import mobb

BLOCK_ROWS = 100_000  # rows per block of a numpy input: ~3 MB of placements, about a second of queries


def _pair(a, b):
    """The task that holds the pair of trees on a worker."""
    return a, b


def _collide_block(placements_a, placements_b, pair, threads):
    """One block's answers, on whichever worker runs it."""
    return mobb.collide_batch(pair[0], pair[1], placements_a, placements_b, threads=threads)


def _blocks(da, placements, what, rows):
    """A Dask array of (k, 4) placements in blocks of rows, each block holding whole rows."""
    p = placements if isinstance(placements, da.Array) else da.from_array(placements, chunks=(rows, 4))
    if p.ndim != 2 or p.shape[1] != 4:
        raise ValueError(f"{what}: expected a (k, 4) array of (x, y, theta, t0), got shape {p.shape}")
    return p.rechunk({1: 4})


def collide_batch(a, b, placements_a, placements_b, *, threads=1, block_rows=BLOCK_ROWS):
    """Row k asks collide(a, placements_a[k], b, placements_b[k]), as mobb.collide_batch, block by block.

    a, b          two mobb.Tree or two mobb.ClipIndex (built once per worker; see the module's doc).
    placements_*  (k, 4) Dask or numpy arrays of (x, y, theta, t0): metres, metres, radians, seconds.
                  placements_b is cut into placements_a's blocks; a numpy placements_a into blocks of
                  block_rows rows.
    threads       threads of each block's mobb.collide_batch (1: one per Dask worker thread).
    Returns a lazy (k,) bool Dask array in placements_a's blocks; .compute() gives the numpy answers.
    Raises ValueError for arrays of other shapes or unequal lengths (mobb's own errors when computed).
    """
    import dask
    import dask.array as da

    pa = _blocks(da, placements_a, "placements_a", block_rows)
    pb = _blocks(da, placements_b, "placements_b", block_rows)
    if pa.shape[0] != pb.shape[0]:
        raise ValueError(f"placements_a, placements_b: {pa.shape[0]} and {pb.shape[0]} rows; expected as many")
    pb = pb.rechunk({0: pa.chunks[0]})
    pair = dask.delayed(_pair)(a, b)
    return da.map_blocks(_collide_block, pa, pb, pair=pair, threads=threads, dtype=bool, drop_axis=1,
                         chunks=(pa.chunks[0],), name="mobb-collide-batch")
