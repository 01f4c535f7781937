// mobb.open_record and mobb.read_record: a crowd record file (JSON or HDF5, crowd/record_reader.h) as
// numpy arrays, a part at a time - a window of frames, a range of agents, the choice points of some
// frames, one choice point whole - so that a long HDF5 record is read only where asked.
#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include <pybind11/stl.h>

#include "bindings.h"
#include "mobb/crowd/record/record_reader.h"

namespace mobb::python {

namespace {

using crowd::RecordReader;

// Calls `f` without the GIL, a file's error as ValueError (with the message `mobb` prints).
template <class F>
auto unlocked(F&& f) -> decltype(f()) {
    try {
        py::gil_scoped_release release;
        return f();
    } catch (const std::runtime_error& e) {
        throw std::invalid_argument(e.what());
    }
}

// An incomplete file opens with a warning saying up to where it is read. A mobb.Record reads its clip
// table now (its properties need it) and keeps recent blocks of frames; read_record reads one window
// and neither.
std::shared_ptr<RecordReader> open(const std::string& file, bool record) {
    auto r = unlocked([&] {
        std::shared_ptr<RecordReader> out = crowd::open_record(file, record ? crowd::kRecordCacheBytes : 0);
        if (record) out->header();
        return out;
    });
    if (!r->info().note.empty()) py::module_::import("warnings").attr("warn")(r->info().note);
    return r;
}

py::object json_dict(const std::string& text) {
    return text.empty() ? py::dict() : py::module_::import("json").attr("loads")(text);
}

// (agent_first, agent_last) from None or a pair.
crowd::AgentRange agent_range(const std::optional<std::pair<std::size_t, std::size_t>>& agents) {
    if (!agents) return {};
    if (agents->first > agents->second) throw std::invalid_argument("agents: expected (first, last), first <= last");
    return {agents->first, agents->second};
}

py::array_t<double> samples_array(const crowd::SampleWindow& w) {
    py::array_t<double> out({py::ssize_t(w.last - w.first), py::ssize_t(w.width()), py::ssize_t(4)});
    if (!w.samples.empty()) std::copy_n(w.samples.data()->data(), w.samples.size() * 4, out.mutable_data());
    return out;
}

template <class T, class F>
py::array_t<T> column(std::size_t n, F&& value) {
    py::array_t<T> out(py::ssize_t(n), nullptr);
    auto v = out.mutable_unchecked();
    for (std::size_t k = 0; k < n; ++k) v(py::ssize_t(k)) = value(k);
    return out;
}

template <class F>
py::array_t<double> rows(std::size_t n, std::size_t width, F&& row) {
    py::array_t<double> out({py::ssize_t(n), py::ssize_t(width)});
    auto v = out.mutable_unchecked();
    for (std::size_t k = 0; k < n; ++k) {
        const auto r = row(k);
        for (std::size_t j = 0; j < width; ++j) v(py::ssize_t(k), py::ssize_t(j)) = r[j];
    }
    return out;
}

py::dict read_record(const std::string& file, std::int64_t first, const std::optional<std::int64_t>& last,
                     const std::optional<std::pair<std::size_t, std::size_t>>& agents) {
    const auto reader = open(file, false);
    const crowd::AgentRange range = agent_range(agents);
    const crowd::SampleWindow w = unlocked(
        [&] { return reader->samples(first, last.value_or(std::numeric_limits<std::int64_t>::max()), range); });
    py::dict out;
    out["samples"] = samples_array(w);
    out["first"] = w.first;
    out["agent_first"] = w.agent_first;
    out["dt"] = w.dt;
    out["frames"] = w.frames;
    out["agents"] = w.agents;
    out["summary"] = json_dict(w.summary_json);
    out["metrics"] = json_dict(w.metrics_json);
    return out;
}

py::dict clips_of(RecordReader& r) {
    std::vector<std::pair<std::size_t, const crowd::PlacedClip*>> all;
    for (std::size_t a = 0; a < r.header().tracks.size(); ++a)
        for (const crowd::PlacedClip& c : r.header().tracks[a].clips) all.emplace_back(a, &c);
    std::stable_sort(all.begin(), all.end(),
                     [](const auto& x, const auto& y) { return x.second->start < y.second->start; });
    py::dict out;
    out["agent"] = column<std::int64_t>(all.size(), [&](std::size_t k) { return std::int64_t(all[k].first); });
    out["clip"] = column<std::int64_t>(all.size(), [&](std::size_t k) { return all[k].second->clip; });
    out["start"] = column<std::int64_t>(all.size(), [&](std::size_t k) { return all[k].second->start; });
    out["fallback"] = column<bool>(all.size(), [&](std::size_t k) { return all[k].second->fallback; });
    out["choice"] = column<std::int64_t>(all.size(), [&](std::size_t k) { return all[k].second->choice; });
    out["place"] = rows(all.size(), 4, [&](std::size_t k) {
        const Placement& p = all[k].second->place;
        return std::array<double, 4>{p.x, p.y, p.theta, p.t0};
    });
    return out;
}

py::dict goals_of(RecordReader& r) {
    std::vector<std::pair<std::size_t, std::array<double, 2>>> all;
    for (std::size_t a = 0; a < r.header().tracks.size(); ++a)
        for (const auto& g : r.header().tracks[a].goals) all.emplace_back(a, g);
    py::dict out;
    out["agent"] = column<std::int64_t>(all.size(), [&](std::size_t k) { return std::int64_t(all[k].first); });
    out["xy"] = rows(all.size(), 2, [&](std::size_t k) { return all[k].second; });
    return out;
}

const char* const kOutcomes[] = {"candidate", "escape", "arrived", "fallback", "right of way"};

std::int64_t outcome_code(const std::string& outcome) {
    return std::int64_t(std::find(std::begin(kOutcomes), std::end(kOutcomes), outcome) - std::begin(kOutcomes));
}

py::dict choices_of(RecordReader& r, std::int64_t first, const std::optional<std::int64_t>& last,
                    const std::optional<int>& agent) {
    const std::vector<crowd::ChoiceSummary> s = unlocked([&] {
        const auto [lo, hi] = r.choice_rows(first, last.value_or(std::numeric_limits<std::int64_t>::max()));
        return r.summaries(lo, hi, agent.value_or(-1));
    });
    const std::size_t n = s.size();
    py::dict out;
    out["row"] = column<std::int64_t>(n, [&](std::size_t k) { return std::int64_t(s[k].row); });
    out["agent"] = column<std::int64_t>(n, [&](std::size_t k) { return s[k].point.agent; });
    out["frame"] = column<std::int64_t>(n, [&](std::size_t k) { return s[k].point.frame; });
    out["taken"] = column<std::int64_t>(n, [&](std::size_t k) { return s[k].point.taken; });
    out["outcome"] = column<std::int64_t>(n, [&](std::size_t k) { return outcome_code(s[k].point.outcome); });
    out["fallback"] = column<bool>(n, [&](std::size_t k) { return s[k].point.fallback; });
    out["candidates"] = column<std::int64_t>(n, [&](std::size_t k) { return std::int64_t(s[k].candidates); });
    out["queries"] = column<std::int64_t>(n, [&](std::size_t k) { return std::int64_t(s[k].point.queries); });
    out["tests2d"] = column<std::int64_t>(n, [&](std::size_t k) { return std::int64_t(s[k].point.tests2d); });
    out["tests3d"] = column<std::int64_t>(n, [&](std::size_t k) { return std::int64_t(s[k].point.tests3d); });
    out["samples"] = column<std::int64_t>(n, [&](std::size_t k) { return std::int64_t(s[k].point.samples); });
    out["pruned"] = column<std::int64_t>(n, [&](std::size_t k) { return std::int64_t(s[k].point.pruned); });
    out["hold_frame"] =
        column<std::int64_t>(n, [&](std::size_t k) { return s[k].point.holds ? s[k].point.hold_frame : -1; });
    out["hold"] = rows(n, 3, [&](std::size_t k) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return s[k].point.holds ? s[k].point.hold : std::array<double, 3>{nan, nan, nan};
    });
    return out;
}

py::array_t<double> framed_array(const std::vector<crowd::FramedClip>& clips) {
    return rows(clips.size(), 5, [&](std::size_t k) {
        const crowd::FramedClip& c = clips[k];
        return std::array<double, 5>{double(c.clip), double(c.frame), c.place.x, c.place.y, c.place.theta};
    });
}

py::dict choice_of(RecordReader& r, std::size_t row) {
    const crowd::ChoicePoint c = unlocked([&] { return r.choice(row); });
    py::list candidates;
    for (const crowd::Candidate& k : c.candidates) {
        py::dict d;
        d["clip"] = k.clip;
        d["leaves_world"] = k.leaves_world;
        d["meets_solid"] = k.meets_solid;
        d["queries"] = k.queries;
        d["hits"] = k.hits;
        d["crowded"] = k.crowded;
        py::array_t<std::int64_t> against({py::ssize_t(k.against.size()), py::ssize_t(5)});
        auto v = against.mutable_unchecked();
        for (std::size_t j = 0; j < k.against.size(); ++j) {
            const crowd::CandidateQuery& q = k.against[j];
            const std::int64_t row_of[5] = {q.agent, crowd::query_index(q), q.piece, q.mine, q.hit};
            for (py::ssize_t i = 0; i < 5; ++i) v(py::ssize_t(j), i) = row_of[i];
        }
        d["against"] = against;
        candidates.append(d);
    }
    py::dict plan;
    plan["escape"] = framed_array(c.escape);
    plan["intended"] = framed_array(c.intended);
    plan["hold"] = c.holds ? py::object(py::make_tuple(c.hold[0], c.hold[1], c.hold[2], c.hold_frame)) : py::none();
    py::list reroutes;
    for (const crowd::ReroutedPlan& p : c.reroutes) {
        py::dict d;
        d["agent"] = p.agent;
        d["escape"] = framed_array(p.escape);
        d["hold"] = py::make_tuple(p.hold[0], p.hold[1], p.hold[2], p.hold_frame);
        reroutes.append(d);
    }
    plan["reroutes"] = reroutes;
    py::dict out;
    out["row"] = row;
    out["agent"] = c.agent;
    out["frame"] = c.frame;
    out["taken"] = c.taken;
    out["outcome"] = c.outcome;
    out["fallback"] = c.fallback;
    out["queries"] = c.queries;
    out["tests2d"] = c.tests2d;
    out["tests3d"] = c.tests3d;
    out["samples"] = c.samples;
    out["pruned"] = c.pruned;
    out["plan"] = plan;
    out["candidates"] = candidates;
    return out;
}

}  // namespace

void add_record(py::module_& m) {
    py::class_<RecordReader, std::shared_ptr<RecordReader>>(
        m, "Record", R"(A crowd record file opened for reading in parts (mobb.open_record).

Of an HDF5 record (`mobb crowd --record r.h5`) only the header, the goals and the clip table are read when
it opens; samples(), choices() and choice() read the frames, the table rows or the choice point asked
(samples through a cache of recent blocks of frames). A JSON record is read whole when it opens.
Units: metres, seconds, radians; frames are global, frame k starts at t = k * dt.)")
        .def_property_readonly(
            "dt", [](RecordReader& r) { return r.header().dt; }, "Seconds per frame")
        .def_property_readonly(
            "frames", [](RecordReader& r) { return r.header().frames; },
            "The run's frames (of an incomplete file: those up to its last mark)")
        .def_property_readonly("agents", [](RecordReader& r) { return r.header().tracks.size(); })
        .def_property_readonly("choice_count", &RecordReader::choice_count, "Rows of the choice table")
        .def_property_readonly("lazy", &RecordReader::lazy, "True when parts are read as asked (HDF5)")
        .def_property_readonly("has_candidates", &RecordReader::has_candidates,
                               "False when the run was recorded without candidates (an HDF5 record unless "
                               "`mobb crowd --record-candidates`): every choice point's list is empty")
        .def_property_readonly("summary", [](RecordReader& r) { return json_dict(r.info().summary_json); })
        .def_property_readonly("metrics", [](RecordReader& r) { return json_dict(r.info().metrics_json); })
        .def_property_readonly(
            "note", [](RecordReader& r) { return r.info().note; },
            "One line when the file is incomplete (read up to its last mark), else empty")
        .def_property_readonly(
            "left_frame",
            [](RecordReader& r) {
                const auto& t = r.header().tracks;
                return column<std::int64_t>(t.size(), [&](std::size_t a) { return t[a].left_frame.value_or(-1); });
            },
            "(agents,) int64: the frame each agent left the run at, -1 for none")
        .def(
            "samples",
            [](RecordReader& r, std::int64_t first, const std::optional<std::int64_t>& last,
               const std::optional<std::pair<std::size_t, std::size_t>>& agents) {
                const crowd::AgentRange range = agent_range(agents);
                return samples_array(unlocked(
                    [&] { return r.samples(first, last.value_or(std::numeric_limits<std::int64_t>::max()), range); }));
            },
            py::arg("first") = 0, py::arg("last") = py::none(), py::arg("agents") = py::none(),
            R"(Frames first .. last - 1 (clamped; last None: to the end) of agents agents[0] .. agents[1] - 1
(None: all), as a (frames, agents, 4) float64 array of disks t, x, y, r; NaN from the frame an agent left
the run on. Of an HDF5 record only the blocks of those frames are read.)")
        .def("clips", &clips_of,
             R"(The clips the agents played, by start frame: dict of arrays agent, clip, start, fallback (bool),
choice (the row of the choice point that took it, -1: an agent's first clip) and place (n, 4) x, y, theta, t0.)")
        .def("goals", &goals_of, "The agents' goals in the order reached: dict of arrays agent and xy (n, 2)")
        .def("choices", &choices_of, py::arg("first") = 0, py::arg("last") = py::none(), py::arg("agent") = py::none(),
             R"(The choice points at frames first .. last - 1 (of one agent when given), without their candidates:
dict of arrays row, agent, frame, taken, outcome (index into mobb.Record.outcomes), fallback (bool),
candidates (how many it tested), queries, tests2d, tests3d, samples, pruned, hold_frame (-1: none) and
hold (n, 3) x, y, r (NaN: none). Of an HDF5 record only those rows are read.)")
        .def("choice", &choice_of, py::arg("row"),
             R"(Choice point `row` whole, as a dict: its fields, its plan (escape and intended (n, 5) arrays of
clip, frame, x, y, theta; hold (x, y, r, frame) or None; reroutes) and its candidates, each a dict with
against, an (n, 5) int64 array of its queries [agent, index, piece, mine, hit] (docs/formats.md).
Raises IndexError for a row past choice_count.)")
        .def(
            "fallbacks",
            [](RecordReader& r) {
                const auto f = unlocked([&] { return r.fallbacks(); });
                py::dict out;
                out["row"] = column<std::int64_t>(f.size(), [&](std::size_t k) { return std::int64_t(f[k].row); });
                out["agent"] = column<std::int64_t>(f.size(), [&](std::size_t k) { return f[k].agent; });
                out["frame"] = column<std::int64_t>(f.size(), [&](std::size_t k) { return f[k].frame; });
                return out;
            },
            "Every choice point that took a fallback: dict of arrays row, agent, frame")
        .def_property_readonly(
            "counts",
            [](RecordReader& r) {
                const crowd::ReadCounts c = r.counts();
                py::dict out;
                out["frames"] = c.frames;
                out["cached"] = c.cached;
                out["choices"] = c.choices;
                out["table_rows"] = c.table_rows;
                return out;
            },
            "What was read so far: frames of samples from the file and from the cache, choice points, table rows")
        .def_property_readonly_static("outcomes", [](const py::object&) {
            py::list out;
            for (const char* o : kOutcomes) out.append(o);
            return out;
        });
    m.def(
        "open_record", [](const std::string& file) { return open(file, true); }, py::arg("file"),
        R"(Opens a crowd record file, `mobb crowd --record` (.json, or HDF5 for .h5 / .hdf5), for reading in
parts: returns a mobb.Record. An incomplete HDF5 record (its writing stopped: killed, a full disk) opens up
to its last mark, with a warning. Raises ValueError "FILE: PLACE: message" for a file that cannot be read,
as `mobb record convert` says it; a JSON record, read whole, whose reading would need more memory than
MOBB_JSON_RECORD_MB megabytes (default 2 GB) is refused before it is parsed, the error naming the memory
and the limit.)");
    m.def("read_record", &read_record, py::arg("file"), py::arg("first") = 0, py::arg("last") = py::none(),
          py::arg("agents") = py::none(),
          R"(Reads frames first .. last - 1 (clamped to the run; last None: to the end) of agents agents[0] ..
agents[1] - 1 (None: all) of a crowd record file, `mobb crowd --record` (.json, or HDF5 for .h5). Of an HDF5
record only those frames are read, so a window of a long run comes back in the time its own size takes; a
JSON record is read whole. mobb.open_record reads more parts of a file opened once.

Returns a dict: samples (frames, agents, 4) float64, each agent's disk t, x, y, r (seconds, metres) at
frames first, first + 1, ..., NaN from the frame an agent left the run on; of an incomplete HDF5 record
(its writing stopped: killed, a full disk) the frames up to its last mark, with a warning saying so; first
(the window's first frame), agent_first (its first agent), dt (seconds per frame), frames and agents (the
run's), summary and metrics (dicts, as `mobb crowd` stores them; empty when the file has none). Raises
ValueError "FILE: PLACE: message" for a file that cannot be read, as `mobb record convert` says it, and
for a JSON record past the memory limit as mobb.open_record does.)");
}

}  // namespace mobb::python
