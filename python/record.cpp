// mobb.read_record: a crowd record file (JSON or HDF5, crowd/record_file.h) as numpy arrays, a window of
// frames at a time, so that a long HDF5 record is read only where asked.
#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>

#include <pybind11/stl.h>

#include "bindings.h"
#include "mobb/crowd/record_file.h"

namespace mobb::python {

namespace {

py::dict read_record(const std::string& file, std::int64_t first, const std::optional<std::int64_t>& last) {
    crowd::SampleWindow w;
    try {
        py::gil_scoped_release release;
        w = crowd::read_sample_window(file, first, last.value_or(std::numeric_limits<std::int64_t>::max()));
    } catch (const std::runtime_error& e) {
        throw std::invalid_argument(e.what());  // ValueError, with the message `mobb` prints
    }
    if (!w.note.empty()) py::module_::import("warnings").attr("warn")(w.note);  // read up to its last mark
    const auto frames = py::ssize_t(w.last - w.first), agents = py::ssize_t(w.agents);
    py::array_t<double> samples({frames, agents, py::ssize_t(4)});
    std::copy_n(w.samples.data()->data(), w.samples.size() * 4, samples.mutable_data());
    const py::object loads = py::module_::import("json").attr("loads");
    py::dict out;
    out["samples"] = samples;
    out["first"] = w.first;
    out["dt"] = w.dt;
    out["frames"] = w.frames;
    out["agents"] = w.agents;
    out["summary"] = w.summary_json.empty() ? py::dict() : loads(w.summary_json);
    out["metrics"] = w.metrics_json.empty() ? py::dict() : loads(w.metrics_json);
    return out;
}

}  // namespace

void add_record(py::module_& m) {
    m.def("read_record", &read_record, py::arg("file"), py::arg("first") = 0, py::arg("last") = py::none(),
          R"(Reads frames first .. last - 1 (clamped to the run; last None: to the end) of a crowd record file,
`mobb crowd --record` (.json, or HDF5 for .h5). Of an HDF5 record only those frames are read, so a window
of a long run comes back in the time its own size takes; a JSON record is read whole.

Returns a dict: samples (frames, agents, 4) float64, each agent's disk t, x, y, r (seconds, metres) at
frames first, first + 1, ..., NaN from the frame an agent left the run on; of an incomplete HDF5 record
(its writing stopped: killed, a full disk) the frames up to its last mark, with a warning saying so; first (the window's first
frame), dt (seconds per frame), frames and agents (the run's), summary and metrics (dicts, as `mobb crowd`
stores them; empty when the file has none). Raises ValueError "FILE: PLACE: message" for a file that
cannot be read, as `mobb record convert` says it.)");
}

}  // namespace mobb::python
