// mobb.crowd: the graph-driven crowd of `mobb crowd` (crowd/crowd.h), its summary, metrics and tracks.
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include <pybind11/stl.h>

#include "bindings.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/record/record_file.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/sim/crowd.h"
#include "mobb/util/worker_pool.h"

namespace mobb::python {

namespace {

struct CrowdArgs {
    std::optional<std::string> graph, scenario, record;
    std::optional<bool> record_candidates;  // none: as the record's kind has it (keeps_candidates)
    std::optional<int> agents;
    std::optional<std::pair<double, double>> world;
    std::optional<double> seconds;
    std::optional<std::string> select;
    std::optional<std::string> tree;
    std::uint64_t seed = 1;
    double cell = 4.0;
    int threads = 0;
};

// The options as `mobb crowd` makes them from its flags: a scenario brings its own world, agents,
// policy and time limit.
crowd::CrowdOptions crowd_options(const CrowdArgs& a, crowd::Scenario& scenario) {
    crowd::CrowdOptions o;
    if (a.scenario) {
        for (const auto& [given, flag] : {std::pair{bool(a.agents), "agents"},
                                          {bool(a.world), "world"},
                                          {bool(a.select), "select"},
                                          {bool(a.seconds), "seconds"}})
            if (given)
                throw std::invalid_argument(std::string("crowd: ") + flag +
                                            " does not go with scenario (the scenario sets it)");
        scenario = crowd::load_scenario(*a.scenario);
        o = crowd::scenario_options(scenario);
    } else {
        if (a.agents) o.agents = *a.agents;
        if (a.world) {
            const auto [w, h] = *a.world;
            if (!(w > 0) || !(h > 0) || !std::isfinite(w) || !std::isfinite(h))
                throw std::invalid_argument("world: expected (width, height) in metres, both positive");
            o.world.x1 = w;
            o.world.y1 = h;
        }
        if (a.seconds) o.seconds = *a.seconds;
        if (a.select) o.select = crowd::parse_selection(*a.select);
        if (o.agents < 1) throw std::invalid_argument("agents: expected at least 1");
        if (!(o.seconds > 0)) throw std::invalid_argument("seconds: expected a positive number");
    }
    // As `mobb crowd`: only a written record shows them, an HDF5 one only when asked.
    if (a.record_candidates && !a.record) throw std::invalid_argument("crowd: record_candidates goes with record");
    o.record_queries = a.record.has_value() && a.record_candidates.value_or(crowd::keeps_candidates(*a.record));
    o.seed = a.seed;
    o.cell = a.cell;
    if (a.threads < 0) throw std::invalid_argument("threads: expected 0 (every core) or more");
    o.threads = a.threads > 0 ? a.threads : util::WorkerPool::hardware_threads();
    return o;
}

// (agents, frames, 4) float64: every agent's disk (t, x, y, r) at every global frame, NaN from the frame
// an agent left the run on.
py::array_t<double> tracks_array(const crowd::Record& record) {
    const auto agents = py::ssize_t(record.tracks.size()), frames = py::ssize_t(record.frames);
    py::array_t<double> out({agents, frames, py::ssize_t(4)});
    auto o = out.mutable_unchecked<3>();
    for (py::ssize_t a = 0; a < agents; ++a) {
        const auto& samples = record.tracks[std::size_t(a)].samples;
        if (py::ssize_t(samples.size()) > frames) throw std::runtime_error("crowd: a track longer than the run");
        for (py::ssize_t f = 0; f < frames; ++f)
            for (py::ssize_t k = 0; k < 4; ++k)
                o(a, f, k) = f < py::ssize_t(samples.size()) ? samples[std::size_t(f)][std::size_t(k)]
                                                             : std::numeric_limits<double>::quiet_NaN();
    }
    return out;
}

// Each agent's goals as a (g, 2) array (g = 0 for one that wanders).
py::list goals_list(const crowd::Record& record) {
    py::list out;
    for (const crowd::AgentTrack& track : record.tracks) {
        py::array_t<double> goals({py::ssize_t(track.goals.size()), py::ssize_t(2)});
        auto g = goals.mutable_unchecked<2>();
        for (std::size_t i = 0; i < track.goals.size(); ++i)
            for (py::ssize_t k = 0; k < 2; ++k) g(py::ssize_t(i), k) = track.goals[i][std::size_t(k)];
        out.append(goals);
    }
    return out;
}

// (agents,) int64: the frame each agent left the run at, -1 for one still in it at the end.
py::array_t<std::int64_t> left_frames(const crowd::Record& record) {
    py::array_t<std::int64_t> out(py::ssize_t(record.tracks.size()));
    auto o = out.mutable_unchecked<1>();
    for (std::size_t a = 0; a < record.tracks.size(); ++a) o(py::ssize_t(a)) = record.tracks[a].left_frame.value_or(-1);
    return out;
}

// Each agent's clips as a (c, 6) array of (clip id, start frame, x, y, theta, t0).
py::list clips_list(const crowd::Record& record) {
    py::list out;
    for (const crowd::AgentTrack& track : record.tracks) {
        py::array_t<double> clips({py::ssize_t(track.clips.size()), py::ssize_t(6)});
        auto c = clips.mutable_unchecked<2>();
        for (std::size_t i = 0; i < track.clips.size(); ++i) {
            const crowd::PlacedClip& p = track.clips[i];
            const auto n = py::ssize_t(i);
            c(n, 0) = p.clip;
            c(n, 1) = double(p.start);
            c(n, 2) = p.place.x;
            c(n, 3) = p.place.y;
            c(n, 4) = p.place.theta;
            c(n, 5) = p.place.t0;
        }
        out.append(clips);
    }
    return out;
}

py::dict run(const CrowdArgs& args) {
    const py::object loads = py::module_::import("json").attr("loads");
    crowd::Scenario scenario;
    const crowd::CrowdOptions options = crowd_options(args, scenario);
    const std::string file = args.graph ? *args.graph : crowd::default_graph_file();
    crowd::CrowdRun result;
    crowd::CrowdMetrics metrics;
    std::string narrow_name;
    TreeOptions tree;
    if (args.tree) tree.type = parse_tree_type(*args.tree);
    {
        py::gil_scoped_release release;
        const crowd::MotionGraph graph = crowd::load_graph(file);
        // The fastest exact query unless a tree is asked for (its counters then fill the summary).
        const crowd::NarrowPhase narrow =
            args.tree ? crowd::NarrowPhase::trees(graph, tree) : crowd::NarrowPhase::sweep(graph);
        narrow_name = narrow.name();
        try {
            result = crowd::run_crowd(graph, narrow, options);
        } catch (const std::invalid_argument& e) {
            if (!args.scenario) throw;
            throw std::invalid_argument(*args.scenario + ": " +
                                        e.what());  // its agents cannot start where it puts them
        }
        result.record.graph = file;
        result.record.scenario = scenario.name;
        metrics = crowd::crowd_metrics(result.record, graph, options.goal_radius);
    }
    const std::string summary = crowd::summary_json(result.summary), metrics_text = crowd::metrics_json(metrics);
    if (args.record) crowd::write_record_file(*args.record, result.record, summary, metrics_text);
    py::dict s = loads(summary);
    s["threads"] = result.summary.threads;
    s["seconds"] = result.summary.seconds;
    s["cd_seconds"] = result.summary.cd_seconds;
    py::dict out;
    out["summary"] = s;
    out["metrics"] = loads(metrics_text);
    out["tracks"] = tracks_array(result.record);
    out["clips"] = clips_list(result.record);
    out["goals"] = goals_list(result.record);
    out["left_frame"] = left_frames(result.record);
    out["dt"] = result.record.dt;
    out["graph"] = file;
    out["narrow_phase"] = narrow_name;
    out["scenario"] = scenario.name;
    return out;
}

}  // namespace

void add_crowd(py::module_& m) {
    m.def(
        "crowd",
        [](const std::optional<std::string>& graph, const std::optional<int>& agents,
           const std::optional<std::pair<double, double>>& world, const std::optional<double>& seconds,
           std::uint64_t seed, const std::optional<std::string>& select, double cell, int threads,
           const std::optional<std::string>& tree, const std::optional<std::string>& scenario,
           const std::optional<std::string>& record, const std::optional<bool>& record_candidates) {
            CrowdArgs a;
            a.graph = graph;
            a.agents = agents;
            a.world = world;
            a.seconds = seconds;
            a.seed = seed;
            a.select = select;
            a.cell = cell;
            a.threads = threads;
            a.tree = tree;
            a.scenario = scenario;
            a.record = record;
            a.record_candidates = record_candidates;
            return run(a);
        },
        py::arg("graph") = py::none(), py::kw_only(), py::arg("agents") = py::none(), py::arg("world") = py::none(),
        py::arg("seconds") = py::none(), py::arg("seed") = 1, py::arg("select") = py::none(), py::arg("cell") = 4.0,
        py::arg("threads") = 0, py::arg("tree") = py::none(), py::arg("scenario") = py::none(),
        py::arg("record") = py::none(), py::arg("record_candidates") = py::none(),
        R"doc(Simulates a graph-driven crowd with collision-free clip choice (paper section 5), as `mobb crowd`.

graph     motion graph JSON (None: assets/graphs/cmu_locomotion.json).
agents    number of agents (default 100); world (width, height) in metres (default (30, 40));
seconds   simulated seconds (default 120); select "wander" (default), "random" or "goal";
seed      random seed; cell broad-phase grid cell (metres); threads (0: every core; the result is the
          same for any count; the GIL is released while it runs);
tree      None: the circle sweep; else a tree type ("mobb", "umobb", ...) whose counters fill the summary;
scenario  a scenario JSON (it sets agents, world, select and seconds); record: write the record there
          (JSON, or HDF5 for .h5; mobb.read_record reads it); record_candidates: keep each choice point's
          candidates and their queries in it (None: in JSON yes, in HDF5 no; docs/formats.md).
Returns a dict: summary (the record's counts, plus threads, seconds and cd_seconds of wall time),
metrics (as `mobb crowd` prints them), tracks ((agents, frames, 4) float64 array of every agent's disk
(t, x, y, r) per frame, seconds and metres; NaN from the frame an agent left the run on), clips (per
agent, a (c, 6) array of clip id, start frame, x, y, theta (radians), t0 (s)), goals (per agent, a
(g, 2) array of its goals in turn, metres; g = 0 when it wanders), left_frame ((agents,) int64: the
frame an agent that leaves at its last goal left the run, -1 otherwise), dt (seconds per frame), graph,
narrow_phase, scenario.)doc");
}

}  // namespace mobb::python
