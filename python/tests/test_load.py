"""mobb.load against `mobb path`: the same samples, with and without loader options."""
import io
import os

import numpy as np
import pytest

import mobb
from conftest import run_cli

CASES = [
    ("cmu/002_01.bvh", []),
    ("cmu/007_03.bvh", ["--frames", "1:"]),
    ("cmu/005_03.bvh", ["--fps", "30", "--scale", "0.01"]),
    ("gltf/002_03.glb", []),
    ("fbx/002_03.fbx", []),
]


def kwargs_of(flags):
    names = {"--frames": "frames", "--fps": "fps", "--scale": "scale", "--up": "up"}
    out = {}
    for flag, value in zip(flags[::2], flags[1::2]):
        out[names[flag]] = float(value) if flag in ("--fps", "--scale") else value
    return out


@pytest.mark.parametrize("name,flags", CASES)
def test_load_equals_mobb_path(data, mobb_exe, name, flags):
    file = os.path.join(data, name)
    code, out, err = run_cli(mobb_exe, "path", file, *flags)
    assert code == 0, err
    expected = np.loadtxt(io.StringIO(out), delimiter=",", skiprows=1)
    clip = mobb.load(file, **kwargs_of(flags))
    assert clip.path.shape == expected.shape
    assert clip.path.dtype == np.float64
    # `mobb path` prints six decimals
    np.testing.assert_allclose(clip.path, expected, rtol=0, atol=5.01e-7)
    np.testing.assert_allclose(clip.path[1:, 0] - clip.path[:-1, 0], clip.dt, rtol=1e-9)


def test_joints_and_info(data):
    clip = mobb.load(os.path.join(data, "cmu", "002_01.bvh"))
    info = clip.info
    n = len(clip)
    assert clip.joints.shape == (n, len(info["joint_names"]), 3)
    assert info["samples"] == n and info["source_frames"] == 171  # the data's README
    assert info["scale_reason"].startswith("auto: ")
    assert len(info["parents"]) == len(info["joint_names"])
    assert info["parents"][info["root"]] == -1
    # r is the largest ground distance from the root's projection to a projected joint (Y-up: x = X,
    # y = -Z), so every joint lies within r of the path on the ground.
    ground = np.stack([clip.joints[:, :, 0], -clip.joints[:, :, 2]], axis=2)
    d = np.linalg.norm(ground - clip.path[:, None, 1:3], axis=2).max(axis=1)
    np.testing.assert_allclose(d, clip.path[:, 3], rtol=1e-9, atol=1e-12)


def test_frames_as_pair(data):
    file = os.path.join(data, "cmu", "007_03.bvh")
    a = mobb.load(file, frames="1:50")
    b = mobb.load(file, frames=(1, 50))
    np.testing.assert_array_equal(a.path, b.path)
    assert len(a) == 49
    assert a.info["source_index"][0] == 1
