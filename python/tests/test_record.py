"""mobb.read_record against `mobb crowd --record`: an HDF5 record reads as the JSON one of the same run,
a window of frames alone; h5py reads the file too; a bad file raises ValueError naming it."""
import json
import os

import numpy as np
import pytest

import mobb
from conftest import SOURCE_DIR, run_cli

GRAPH = os.path.join(SOURCE_DIR, "assets", "graphs", "cmu_locomotion.json")
# Without the motion metrics: a streamed HDF5 run keeps no clips to pose, a JSON one would have them.
RUN = ["crowd", "--quiet", "--no-motion", "--graph", GRAPH, "--agents", "10", "--world", "12x12", "--seconds", "6", "--seed", "4"]


def record_both_ways(mobb_exe, folder, run):
    """The run `run` recorded as JSON and as HDF5: {"json": path, "h5": path}."""
    out = {}
    for kind in ("json", "h5"):
        out[kind] = folder / ("record." + kind)
        code, _, err = run_cli(mobb_exe, *run, "--record", str(out[kind]))
        assert code == 0, err
    return out


@pytest.fixture(scope="module")
def records(tmp_path_factory, mobb_exe):
    return record_both_ways(mobb_exe, tmp_path_factory.mktemp("records"), RUN)


def test_hdf5_reads_as_the_json(records):
    expected = json.loads(records["json"].read_text())
    for kind in ("json", "h5"):
        r = mobb.read_record(str(records[kind]))
        assert r["samples"].shape == (expected["frames"], 10, 4) and r["samples"].dtype == np.float64
        np.testing.assert_array_equal(r["samples"], np.array([t["samples"] for t in expected["tracks"]]).swapaxes(0, 1))
        assert r["summary"] == expected["summary"] and r["metrics"] == expected["metrics"]
        assert (r["dt"], r["frames"], r["agents"], r["first"]) == (expected["dt"], expected["frames"], 10, 0)


def test_a_window_of_frames(records):
    whole = mobb.read_record(str(records["h5"]))["samples"]
    window = mobb.read_record(str(records["h5"]), first=50, last=80)
    assert window["first"] == 50
    np.testing.assert_array_equal(window["samples"], whole[50:80])
    assert mobb.read_record(str(records["h5"]), first=170, last=1000)["samples"].shape == (10, 10, 4)


def test_h5py_reads_it(records):
    h5py = pytest.importorskip("h5py")
    with h5py.File(records["h5"], "r") as f:
        fmt = f.attrs["format"]  # fixed-length text: bytes in h5py
        assert (fmt.decode() if isinstance(fmt, bytes) else fmt) == "mobb crowd record"
        np.testing.assert_array_equal(f["tracks/samples"][20:30], mobb.read_record(str(records["h5"]), 20, 30)["samples"])
        assert len(f["choices/agent"]) == json.loads(records["json"].read_text())["summary"]["choice_points"]


def test_bad_files(tmp_path, records):
    cut = tmp_path / "cut.h5"
    cut.write_bytes(records["h5"].read_bytes()[:5000])
    with pytest.raises(ValueError, match="cut.h5: "):
        mobb.read_record(str(cut))
    with pytest.raises(ValueError, match="missing.json: cannot open"):
        mobb.read_record(str(tmp_path / "missing.json"))


@pytest.mark.parametrize("name, value, field", [("dt", 0.0, "dt"), ("frames", 0, "frames"), ("world", [0, 0, -1, 5], "world")])
def test_an_hdf5_field_out_of_range_names_itself(tmp_path, records, mobb_exe, name, value, field):
    # An HDF5 record goes through the same field checks as a JSON one: a well-formed file holding a
    # value that makes no sense is refused in one line naming the file and the field, exit 1.
    h5py = pytest.importorskip("h5py")
    bad = tmp_path / ("bad_" + name + ".h5")
    bad.write_bytes(records["h5"].read_bytes())
    with h5py.File(bad, "r+") as f:
        f.attrs.modify(name, np.array(value, dtype=f.attrs[name].dtype))
    code, out, err = run_cli(mobb_exe, "record", "convert", str(bad), str(tmp_path / "out.json"))
    assert code == 1 and out == "" and err.count("\n") == 1, err
    assert str(bad) in err and field in err, err
    assert not (tmp_path / "out.json").exists()


# Two blocks of frames (256 and 104 at 20 agents), written as the run went; the JSON record of the same run.
LONG = ["crowd", "--quiet", "--no-motion", "--graph", GRAPH, "--agents", "20", "--world", "8x9", "--seconds", "12", "--seed", "2"]


@pytest.fixture(scope="module")
def long_records(tmp_path_factory, mobb_exe):
    return record_both_ways(mobb_exe, tmp_path_factory.mktemp("long"), LONG + ["--record-candidates"])


def test_open_record_reads_only_the_window_asked(long_records):
    expected = json.loads(long_records["json"].read_text())
    samples = np.array([t["samples"] for t in expected["tracks"]]).swapaxes(0, 1)
    r = mobb.open_record(str(long_records["h5"]))
    assert r.lazy and (r.frames, r.agents, r.dt) == (360, 20, expected["dt"])
    assert r.counts["frames"] == 0
    np.testing.assert_array_equal(r.samples(300, 310, agents=(5, 9)), samples[300:310, 5:9])
    assert r.counts["frames"] == 104  # the second block alone
    np.testing.assert_array_equal(r.samples(), samples)
    assert r.counts["frames"] == 360 and r.counts["cached"] == 104
    window = mobb.read_record(str(long_records["h5"]), 100, 120, agents=(3, 4))
    np.testing.assert_array_equal(window["samples"], samples[100:120, 3:4])
    assert (window["first"], window["agent_first"], window["agents"]) == (100, 3, 20)


def test_open_record_clips_and_choices_are_the_records(long_records):
    expected = json.loads(long_records["json"].read_text())
    for kind in ("h5", "json"):
        r = mobb.open_record(str(long_records[kind]))
        clips = sorted(((c["start"], a, c) for a, t in enumerate(expected["tracks"]) for c in t["clips"]),
                       key=lambda x: x[0])
        got = r.clips()
        assert list(got["agent"]) == [a for _, a, _ in clips]
        assert list(got["clip"]) == [c["clip"] for _, _, c in clips]
        assert list(got["choice"]) == [c["choice"] for _, _, c in clips]
        np.testing.assert_array_equal(got["place"], np.array([c["place"] for _, _, c in clips]))
        choices = expected["choices"]
        assert r.choice_count == len(choices)
        table = r.choices(100, 200)
        rows = [k for k, c in enumerate(choices) if 100 <= c["frame"] < 200]
        assert list(table["row"]) == rows
        for name in ("agent", "frame", "taken", "queries", "tests2d", "samples", "pruned"):
            assert list(table[name]) == [choices[k][name] for k in rows], name
        assert [mobb.Record.outcomes[o] for o in table["outcome"]] == [choices[k]["outcome"] for k in rows]
        assert list(table["candidates"]) == [len(choices[k]["candidates"]) for k in rows]
        assert list(r.choices(100, 200, agent=4)["row"]) == [k for k in rows if choices[k]["agent"] == 4]
        for k in rows[::7]:
            c, want = r.choice(k), choices[k]
            assert (c["agent"], c["frame"], c["taken"], c["outcome"]) == (want["agent"], want["frame"], want["taken"], want["outcome"])
            assert len(c["candidates"]) == len(want["candidates"])
            for got_cand, want_cand in zip(c["candidates"], want["candidates"]):
                assert got_cand["clip"] == want_cand["clip"] and got_cand["hits"] == want_cand["hits"]
                np.testing.assert_array_equal(got_cand["against"], np.array(want_cand["against"], dtype=np.int64).reshape(-1, 5))
            np.testing.assert_array_equal(c["plan"]["escape"], np.array(want["plan"]["escape"], dtype=float).reshape(-1, 5))
        with pytest.raises(IndexError):
            r.choice(len(choices))


def test_open_record_of_a_run_recorded_without_candidates(records, long_records):
    # `mobb crowd --record r.h5` keeps no candidates unless asked; r.json and --record-candidates do.
    bare, kept = mobb.open_record(str(records["h5"])), mobb.open_record(str(records["json"]))
    assert not bare.has_candidates and kept.has_candidates
    assert mobb.open_record(str(long_records["h5"])).has_candidates
    assert bare.choice_count == kept.choice_count > 0
    table, whole = bare.choices(0, bare.frames), kept.choices(0, kept.frames)
    assert not table["candidates"].any() and whole["candidates"].any()
    for name in ("agent", "frame", "taken", "queries", "tests2d"):
        np.testing.assert_array_equal(table[name], whole[name], err_msg=name)
    assert bare.choice(bare.choice_count - 1)["candidates"] == []


def test_open_record_refuses_a_cut_file_in_one_line(tmp_path, long_records):
    cut = tmp_path / "cut.h5"
    cut.write_bytes(long_records["h5"].read_bytes()[:20000])
    with pytest.raises(ValueError, match="cut.h5: ") as e:
        mobb.open_record(str(cut))
    assert "\n" not in str(e.value)


def test_a_json_record_past_the_memory_limit_is_refused(monkeypatch, records):
    # A JSON record is read whole: past MOBB_JSON_RECORD_MB (a small limit here; 2 GB unless set) it is
    # refused before it is parsed, in one line naming the file, the memory it would need and the limit; an
    # HDF5 record is read in parts and not limited.
    monkeypatch.setenv("MOBB_JSON_RECORD_MB", "0.01")
    for read in (mobb.open_record, mobb.read_record):
        with pytest.raises(ValueError) as e:
            read(str(records["json"]))
        message = str(e.value)
        assert message.startswith(str(records["json"]) + ": reading this JSON record") and "\n" not in message
        assert "over the limit of 0.01 MB (MOBB_JSON_RECORD_MB)" in message and "mobb record convert" in message
        assert read(str(records["h5"])) is not None
    monkeypatch.setenv("MOBB_JSON_RECORD_MB", "100")
    assert mobb.open_record(str(records["json"])).agents == 10
