"""mobb.crowd_poses: the poses `mobb export-crowd` writes, roots on the record's tracks, every joint inside
the disk r(t), and the BVH export read back by mobb.load giving the same root path."""
import json
import os

import numpy as np
import pytest

import mobb
from conftest import SOURCE_DIR, run_cli

GRAPH = os.path.join(SOURCE_DIR, "assets", "graphs", "cmu_locomotion.json")


@pytest.fixture(scope="module")
def record(tmp_path_factory):
    if not mobb_data():
        pytest.skip("mocap data not found: set MOBB_DATA or put it in ../shared/mocap")
    path = tmp_path_factory.mktemp("poses") / "record.json"
    mobb.crowd(GRAPH, agents=5, world=(9, 9), seconds=6, seed=2, threads=1, record=str(path))
    return path


def mobb_data():
    folder = os.environ.get("MOBB_DATA") or os.path.join(SOURCE_DIR, "..", "shared", "mocap")
    return os.path.isfile(os.path.join(folder, "cmu", "007_01.bvh"))


def test_poses_stand_on_the_tracks_inside_their_disks(record):
    expected = json.loads(record.read_text())
    poses = mobb.crowd_poses(str(record))
    names, parents = mobb.crowd_joints(str(record))
    assert poses.shape == (5, expected["frames"], len(names), 3) and poses.dtype == np.float64
    assert parents[0] == -1
    tracks = np.array([t["samples"] for t in expected["tracks"]])
    np.testing.assert_allclose(poses[:, :, 0, :2], tracks[:, :, 1:3], atol=1e-4)
    ground = np.linalg.norm(poses[:, :, :, :2] - poses[:, :, :1, :2], axis=3)
    assert (ground.max(axis=2) <= tracks[:, :, 3] + 1e-9).all()


def test_times_and_agents_pick_frames(record):
    dt = json.loads(record.read_text())["dt"]
    every = mobb.crowd_poses(str(record), joints="major")
    some = mobb.crowd_poses(str(record), [3, 1], [10 * dt, 40 * dt], joints="major")
    np.testing.assert_allclose(some, every[[3, 1]][:, [10, 40]], atol=1e-12)


def test_bad_agents_and_times_are_refused(record):
    with pytest.raises(ValueError, match=r"agents\[1\]: agent 5 is not in the record \(5 agents\)"):
        mobb.crowd_poses(str(record), [0, 5])
    with pytest.raises(ValueError, match=r"times\[0\]: expected seconds in"):
        mobb.crowd_poses(str(record), None, [-1.0])
    with pytest.raises(ValueError, match="joints"):
        mobb.crowd_poses(str(record), joints="some")


def test_bvh_export_reads_back_as_the_track(record, tmp_path, mobb_exe):
    code, out, err = run_cli(mobb_exe, "export-crowd", str(record), "--format", "bvh", "--out", str(tmp_path),
                             "--agents", "2:3")
    assert code == 0, err
    clip = mobb.load(str(tmp_path / "agent_2.bvh"))
    poses = mobb.crowd_poses(str(record), [2])
    np.testing.assert_allclose(clip.path[:, 1:3], poses[0, :, 0, :2], atol=1e-3)


def test_export_and_python_give_the_same_locked_feet(record, tmp_path, mobb_exe):
    code, out, err = run_cli(mobb_exe, "export-crowd", str(record), "--format", "bvh", "--out", str(tmp_path),
                             "--agents", "1:2", "--joints", "major")
    assert code == 0, err
    names, _ = mobb.crowd_joints(str(record), joints="major")
    clip = mobb.load(str(tmp_path / "agent_1.bvh"))
    locked = mobb.crowd_poses(str(record), [1], joints="major")
    free = mobb.crowd_poses(str(record), [1], joints="major", lock_feet=False)
    feet = [names.index(n) for n in names if n.endswith("_Foot") or n.endswith("_ToeBase")]
    assert np.abs(locked[0, :, feet] - free[0, :, feet]).max() > 0.005  # metres: locking moved the feet
    # BVH is Y up: a joint's x is mobb's x, its height the file's y.
    loaded = clip.info["joint_names"]
    written = clip.joints[:, [loaded.index(names[j]) for j in feet]]
    np.testing.assert_allclose(written[:, :, 0], locked[0][:, feet, 0], atol=1e-5)
    np.testing.assert_allclose(written[:, :, 1], locked[0][:, feet, 2], atol=1e-5)
