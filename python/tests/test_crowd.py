"""mobb.crowd against `mobb crowd --record`: the same summary counts and tracks."""
import json
import os

import numpy as np
import pytest

import mobb
from conftest import SOURCE_DIR, run_cli

GRAPH = os.path.join(SOURCE_DIR, "assets", "graphs", "cmu_locomotion.json")


def test_crowd_equals_mobb_crowd(tmp_path, mobb_exe):
    record = tmp_path / "record.json"
    code, _, err = run_cli(mobb_exe, "crowd", "--quiet", "--graph", GRAPH, "--agents", "12", "--world", "12x12",
                           "--seconds", "8", "--seed", "3", "--threads", "2", "--record", str(record))
    assert code == 0, err
    expected = json.loads(record.read_text())

    run = mobb.crowd(GRAPH, agents=12, world=(12, 12), seconds=8, seed=3, threads=1)
    summary = run["summary"]
    assert {k: summary[k] for k in expected["summary"]} == expected["summary"]
    assert summary["threads"] == 1 and summary["seconds"] > 0
    # The command line adds the motion metrics (they need the mocap); mobb.crowd has the others.
    assert run["metrics"] == {k: v for k, v in expected["metrics"].items() if k != "motion"}
    tracks = run["tracks"]
    assert tracks.shape == (12, expected["frames"], 4) and tracks.dtype == np.float64
    np.testing.assert_array_equal(tracks, np.array([t["samples"] for t in expected["tracks"]]))
    assert run["dt"] == expected["dt"]
    for clips, track in zip(run["clips"], expected["tracks"]):
        np.testing.assert_array_equal(clips[:, 0], [c["clip"] for c in track["clips"]])
        np.testing.assert_array_equal(clips[:, 2:], [c["place"] for c in track["clips"]])
    assert summary["queries"] > 0 and summary["choice_points"] > 0


def test_crowd_records_candidates_as_mobb_crowd(tmp_path):
    # A JSON record keeps the choice points' candidates, an HDF5 one only when asked; the choice points
    # and their counts are there either way.
    run = dict(agents=8, world=(10, 10), seconds=4, seed=2, threads=1)
    mobb.crowd(GRAPH, record=str(tmp_path / "r.json"), **run)
    choices = json.loads((tmp_path / "r.json").read_text())["choices"]
    assert sum(len(c["candidates"]) for c in choices) > 0
    h5py = pytest.importorskip("h5py")
    for asked, kept in ((None, False), (True, True)):
        file = tmp_path / ("r_%s.h5" % asked)
        mobb.crowd(GRAPH, record=str(file), record_candidates=asked, **run)
        with h5py.File(file, "r") as f:
            assert len(f["choices/agent"]) == len(choices)
            assert (len(f["candidates/choice"]) > 0) == kept and (len(f["queries/hit"]) > 0) == kept
    with pytest.raises(ValueError, match="record_candidates goes with record"):
        mobb.crowd(GRAPH, record_candidates=True, **run)


def test_crowd_scenario_refuses_its_own_options():
    folder = os.path.join(SOURCE_DIR, "assets", "scenarios")
    scenario = os.path.join(folder, sorted(f for f in os.listdir(folder) if f.endswith(".json"))[0])
    with pytest.raises(ValueError, match="agents does not go with scenario"):
        mobb.crowd(scenario=scenario, agents=3)


def test_crowd_agents_that_leave_and_goal_sequences():
    folder = os.path.join(SOURCE_DIR, "assets", "scenarios")
    run = mobb.crowd(scenario=os.path.join(folder, "fan_in_exit.json"), threads=1)
    left = run["left_frame"]
    assert left.shape == (6,) and left.dtype == np.int64
    assert (left > 0).all() and (left < run["tracks"].shape[1]).all()
    for a, frame in enumerate(left):
        assert not np.isnan(run["tracks"][a, :frame]).any()
        assert np.isnan(run["tracks"][a, frame:]).all()  # gone from the run
        np.testing.assert_array_equal(run["goals"][a], [[0, 20]])
    assert run["metrics"]["left"] == 6
    run = mobb.crowd(scenario=os.path.join(folder, "waypoints.json"), threads=1)
    assert all(g.shape == (3, 2) for g in run["goals"])
    assert (run["left_frame"] == -1).all()
