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


@pytest.fixture(scope="module")
def records(tmp_path_factory, mobb_exe):
    folder = tmp_path_factory.mktemp("records")
    out = {}
    for kind in ("json", "h5"):
        out[kind] = folder / ("record." + kind)
        code, _, err = run_cli(mobb_exe, *RUN, "--record", str(out[kind]))
        assert code == 0, err
    return out


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
