"""Bad input raises Python exceptions carrying the command line's messages."""
import os

import numpy as np
import pytest

import mobb
from conftest import cli_error


def test_missing_file(tmp_path, mobb_exe):
    missing = str(tmp_path / "no_such.bvh")
    with pytest.raises(mobb.LoadError) as e:
        mobb.load(missing)
    assert str(e.value) == cli_error(mobb_exe, "path", missing)


def test_malformed_bvh(tmp_path, mobb_exe):
    bad = tmp_path / "bad.bvh"
    bad.write_text("HIERARCHY\nROOT hips\n{\n  OFFSET 0 0\n")
    with pytest.raises(mobb.LoadError) as e:
        mobb.load(bad)
    assert str(e.value) == cli_error(mobb_exe, "path", str(bad))
    assert str(e.value).startswith(str(bad) + ":")


def test_unknown_extension(tmp_path, mobb_exe):
    odd = tmp_path / "clip.txt"
    odd.write_text("x")
    with pytest.raises(mobb.LoadError) as e:
        mobb.load(str(odd))
    assert str(e.value) == cli_error(mobb_exe, "path", str(odd))


def test_bad_loader_options(data, mobb_exe):
    file = os.path.join(data, "cmu", "002_01.bvh")
    for kwargs, flags in [({"frames": "5:2"}, ["--frames", "5:2"]),
                          ({"frames": "0:100000"}, ["--frames", "0:100000"]),
                          ({"scale": "abc"}, ["--scale", "abc"])]:
        with pytest.raises(ValueError) as e:
            mobb.load(file, **kwargs)
        assert str(e.value) == cli_error(mobb_exe, "path", file, *flags), kwargs
    with pytest.raises(ValueError, match="--fps -1 must be finite and positive"):
        mobb.load(file, fps=-1)


def test_bad_graph(tmp_path, mobb_exe):
    bad = tmp_path / "graph.json"
    bad.write_text("{\"clips\": 3}")
    with pytest.raises(mobb.GraphError) as e:
        mobb.crowd(str(bad), agents=2, seconds=1)
    assert str(e.value) == cli_error(mobb_exe, "crowd", "--quiet", "--graph", str(bad), "--agents", "2",
                                     "--seconds", "1")


def test_bad_tree_and_placements(data):
    clip = mobb.load(os.path.join(data, "cmu", "002_01.bvh"))
    with pytest.raises(ValueError, match="umobb"):  # names the valid types
        mobb.Tree(clip, type="octree")
    with pytest.raises(ValueError):
        mobb.Tree(clip, n_min=0)
    with pytest.raises(ValueError, match="path"):
        mobb.Tree(np.zeros((5, 3)))
    with pytest.raises(ValueError, match="path: .*r"):
        mobb.Tree(np.array([[0, 0, 0, -1.0], [1, 0, 0, 1.0]]))
    t = mobb.Tree(clip)
    with pytest.raises(ValueError, match="pa: expected"):
        mobb.collide(t, (0, 0, 0), t, (0, 0, 0, 0))
    with pytest.raises(ValueError, match="pb: not finite"):
        mobb.collide(t, (0, 0, 0, 0), t, (0, float("nan"), 0, 0))
    with pytest.raises(TypeError):
        mobb.collide(t, (0, 0, 0, 0), clip, (0, 0, 0, 0))
    good = np.zeros((3, 4))
    with pytest.raises(ValueError, match=r"placements_b\[1\]: not finite"):
        mobb.collide_batch(t, t, good, np.array([[0, 0, 0, 0], [np.inf, 0, 0, 0], [0, 0, 0, 0]]))
    with pytest.raises(ValueError, match="as many"):
        mobb.collide_batch(t, t, good, np.zeros((2, 4)))
    with pytest.raises(ValueError, match=r"\(k, 4\)"):
        mobb.collide_batch(t, t, good, np.zeros((3, 3)))
