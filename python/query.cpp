// mobb.Tree, mobb.ClipIndex, mobb.collide, mobb.collide_batch, mobb.clearance: the core's queries
// (core/query.h, sweep.h, brute.h, clearance.h) on clips placed by (x, y, theta, t0) in radians.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "mobb/core/brute.h"
#include "mobb/core/clearance.h"
#include "mobb/core/clip_index.h"
#include "mobb/core/fit.h"
#include "mobb/core/query.h"
#include "mobb/core/sweep.h"
#include "mobb/core/tree.h"
#include "mobb/io/load.h"
#include "mobb/util/worker_pool.h"

namespace mobb::python {

namespace {

// Which query a pair of Python objects asks for: trees (collide), clip indexes (collide_sweep) or
// loaded clips (collide_brute, the reference).
enum class Method { Trees, Sweep, Brute };

Method method_of(const py::handle& a, const py::handle& b) {
    if (py::isinstance<Tree>(a) && py::isinstance<Tree>(b)) return Method::Trees;
    if (py::isinstance<ClipIndex>(a) && py::isinstance<ClipIndex>(b)) return Method::Sweep;
    if (py::isinstance<io::Clip>(a) && py::isinstance<io::Clip>(b)) return Method::Brute;
    throw py::type_error("a, b: expected two mobb.Tree, two mobb.ClipIndex or two mobb.Clip (brute force)");
}

// One pair's query with its objects resolved: read-only, so any thread may run it.
struct Pair {
    Method method = Method::Trees;
    const void* a = nullptr;
    const void* b = nullptr;

    bool operator()(const Placement& pa, const Placement& pb, QueryStats* stats = nullptr, Trace* trace = nullptr,
                    SamplePair* hit = nullptr) const {
        switch (method) {
            case Method::Trees:
                return collide(*static_cast<const Tree*>(a), pa, *static_cast<const Tree*>(b), pb, stats, trace, hit);
            case Method::Sweep:
                return collide_sweep(*static_cast<const ClipIndex*>(a), pa, *static_cast<const ClipIndex*>(b), pb, hit);
            case Method::Brute:
                return collide_brute(static_cast<const io::Clip*>(a)->path, pa, static_cast<const io::Clip*>(b)->path,
                                     pb, stats, hit);
        }
        return false;
    }
};

Pair pair_of(const py::handle& a, const py::handle& b) {
    Pair p;
    p.method = method_of(a, b);
    switch (p.method) {
        case Method::Trees:
            p.a = &a.cast<const Tree&>();
            p.b = &b.cast<const Tree&>();
            break;
        case Method::Sweep:
            p.a = &a.cast<const ClipIndex&>();
            p.b = &b.cast<const ClipIndex&>();
            break;
        case Method::Brute:
            p.a = &a.cast<const io::Clip&>();
            p.b = &b.cast<const io::Clip&>();
            break;
    }
    return p;
}

py::list trace_list(const Trace& trace) {
    py::list out;
    for (const TraceEvent& e : trace) {
        py::dict d;
        d["node_a"] = e.node_a;
        d["node_b"] = e.node_b;
        d["test"] = to_string(e.test);
        d["outcome"] = to_string(e.outcome);
        d["sample_a"] = e.sample_a;
        d["sample_b"] = e.sample_b;
        d["samples_tested"] = e.samples_tested;
        out.append(d);
    }
    return out;
}

py::object collide_one(const py::handle& a, const py::handle& pa, const py::handle& b, const py::handle& pb,
                       bool counters, bool trace) {
    const Pair pair = pair_of(a, b);
    const Placement place_a = placement_from(pa, "pa"), place_b = placement_from(pb, "pb");
    if (!counters && !trace) return py::bool_(pair(place_a, place_b));
    if (pair.method == Method::Sweep)
        throw std::invalid_argument("counters and the trace come from the trees: pass two mobb.Tree");
    if (trace && pair.method != Method::Trees)
        throw std::invalid_argument("the trace comes from the trees: pass two mobb.Tree");
    QueryStats stats;
    Trace events;
    SamplePair hit;
    const bool collides = pair(place_a, place_b, &stats, trace ? &events : nullptr, &hit);
    py::dict d;  // the keys of `mobb query`'s JSON, then the pair found and the trace
    d["collide"] = collides;
    d["tests2d"] = stats.tests2d;
    d["tests3d"] = stats.tests3d;
    d["samples"] = stats.samples;
    d["pair"] = collides ? py::object(py::make_tuple(hit.a, hit.b)) : py::object(py::none());
    if (trace) d["trace"] = trace_list(events);
    return std::move(d);
}

std::vector<Placement> placements_from(const py::handle& object, const std::string& what) {
    const auto rows = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!rows || rows.ndim() != 2 || rows.shape(1) != 4)
        throw std::invalid_argument(
            what + ": expected a (k, 4) array of (x, y, theta, t0) (metres, metres, radians, seconds)");
    const auto r = rows.unchecked<2>();
    std::vector<Placement> out(std::size_t(rows.shape(0)));
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
        for (py::ssize_t k = 0; k < 4; ++k)
            if (!std::isfinite(r(i, k))) throw std::invalid_argument(what + "[" + std::to_string(i) + "]: not finite");
        out[std::size_t(i)] = {r(i, 0), r(i, 1), r(i, 2), r(i, 3)};
    }
    return out;
}

py::array_t<bool> collide_batch(const py::handle& a, const py::handle& b, const py::handle& placements_a,
                                const py::handle& placements_b, int threads) {
    const Pair pair = pair_of(a, b);
    const std::vector<Placement> pa = placements_from(placements_a, "placements_a");
    const std::vector<Placement> pb = placements_from(placements_b, "placements_b");
    if (pa.size() != pb.size())
        throw std::invalid_argument("placements_a, placements_b: " + std::to_string(pa.size()) + " and " +
                                    std::to_string(pb.size()) + " rows; expected as many");
    if (threads < 0)
        throw std::invalid_argument("threads: expected 0 (every core) or more, got " + std::to_string(threads));
    std::vector<std::uint8_t> hits(pa.size());
    {
        py::gil_scoped_release release;
        util::WorkerPool pool(threads > 0 ? threads : util::WorkerPool::hardware_threads());
        pool.for_each(
            pa.size(), [&](std::size_t k, int) { hits[k] = pair(pa[k], pb[k]) ? 1 : 0; }, 16);
    }
    py::array_t<bool> out(py::ssize_t(hits.size()));
    auto o = out.mutable_unchecked<1>();
    for (std::size_t k = 0; k < hits.size(); ++k) o(py::ssize_t(k)) = hits[k] != 0;
    return out;
}

py::dict clearance_of(const py::handle& a, const py::handle& pa, const py::handle& b, const py::handle& pb) {
    const std::vector<ClearanceSample> c = clearance(path_from(a, py::none(), "a"), placement_from(pa, "pa"),
                                                     path_from(b, py::none(), "b"), placement_from(pb, "pb"));
    py::array_t<double> t(py::ssize_t(c.size())), gap(py::ssize_t(c.size()));
    py::array_t<std::int64_t> i(py::ssize_t(c.size())), j(py::ssize_t(c.size()));
    for (std::size_t k = 0; k < c.size(); ++k) {
        const auto n = py::ssize_t(k);
        t.mutable_at(n) = c[k].t;
        gap.mutable_at(n) = c[k].gap;
        i.mutable_at(n) = c[k].i;
        j.mutable_at(n) = c[k].j;
    }
    py::dict d;
    d["t"] = t;
    d["gap"] = gap;
    d["i"] = i;
    d["j"] = j;
    return d;
}

// A Tree or ClipIndex pickles as what builds it - its path (rows t, x, y, r), dt and, for a tree, its
// options - and unpickles by building it again: the same path and options give the same tree, so a
// copy answers every query as the original does. Dask ships them to its workers so (mobb_dask.py).
const char* fit_name(AxisFit fit) { return fit == AxisFit::Pca ? "pca" : "chord"; }

py::tuple tree_state(const Tree& t) {
    return py::make_tuple(path_array(t.path()), t.path().dt, to_string(t.options().type), t.options().n_min,
                          fit_name(t.options().fit));
}

Tree tree_of_state(const py::tuple& s) {
    if (s.size() != 5) throw std::invalid_argument("mobb.Tree: bad pickled state");
    return Tree::build(path_from(s[0], s[1], "path"),
                       parse_tree_options(s[2].cast<std::string>(), s[3].cast<int>(), s[4].cast<std::string>()));
}

py::tuple index_state(const ClipIndex& c) { return py::make_tuple(path_array(c.path()), c.path().dt); }

ClipIndex index_of_state(const py::tuple& s) {
    if (s.size() != 2) throw std::invalid_argument("mobb.ClipIndex: bad pickled state");
    return ClipIndex::build(path_from(s[0], s[1], "path"));
}

}  // namespace

void add_query(py::module_& m) {
    py::class_<Tree>(m, "Tree",
                     R"doc(A clip's MOBB / UMOBB tree (paper section 3), built once, queried under any placement.

Tree(path, type="mobb", n_min=10, fit="chord", dt=None)
  path   a mobb.Clip, or an (n, 4) array of (t, x, y, r) (seconds, metres) with sample spacing dt
         (default t[1] - t[0]).
  type   "mobb", "umobb", "hybrid1", "hybrid2", "mobb1" or "umobb1" (the command line's --tree).
  n_min  most samples in a leaf (>= 1).
  fit    MOBB axis fit: "chord" (the paper's) or "pca".
Raises ValueError for an empty or invalid path or a bad option. Pickles as its path and options (a copy
is built again from them), so Dask and multiprocessing can ship it.)doc")
        .def(py::init([](const py::object& path, const std::string& type, int n_min, const std::string& fit,
                         const py::object& dt) {
                 return Tree::build(path_from(path, dt, "path"), parse_tree_options(type, n_min, fit));
             }),
             py::arg("path"), py::arg("type") = "mobb", py::arg("n_min") = 10, py::arg("fit") = "chord",
             py::arg("dt") = py::none())
        .def(py::pickle(&tree_state, &tree_of_state))
        .def_property_readonly("type", [](const Tree& t) { return to_string(t.options().type); })
        .def_property_readonly("n_min", [](const Tree& t) { return t.options().n_min; })
        .def_property_readonly(
            "nodes", [](const Tree& t) { return t.nodes().size(); }, "number of nodes")
        .def_property_readonly("depth", &Tree::depth, "number of levels")
        .def_property_readonly(
            "path", [](const Tree& t) { return path_array(t.path()); },
            "(n, 4) float64 array of (t, x, y, r), seconds and metres")
        .def_property_readonly(
            "dt", [](const Tree& t) { return t.path().dt; }, "seconds between samples")
        .def("__len__", [](const Tree& t) { return t.path().size(); });

    py::class_<ClipIndex>(m, "ClipIndex", R"doc(A clip prepared for the circle sweep, the library's fastest exact query.

ClipIndex(path, dt=None): path as for mobb.Tree. Raises ValueError for an empty or invalid path, more
than 2^21 samples or coordinates beyond 1e9 m. Pickles as its path (built again), as a Tree does.)doc")
        .def(py::init([](const py::object& path, const py::object& dt) {
                 return ClipIndex::build(path_from(path, dt, "path"));
             }),
             py::arg("path"), py::arg("dt") = py::none())
        .def(py::pickle(&index_state, &index_of_state))
        .def_property_readonly("levels", &ClipIndex::levels, "levels of the circle hierarchy")
        .def_property_readonly(
            "path", [](const ClipIndex& c) { return path_array(c.path()); },
            "(n, 4) float64 array of (t, x, y, r), seconds and metres")
        .def_property_readonly(
            "dt", [](const ClipIndex& c) { return c.path().dt; }, "seconds between samples")
        .def("__len__", &ClipIndex::size);

    m.def("collide", &collide_one, py::arg("a"), py::arg("pa"), py::arg("b"), py::arg("pb"), py::kw_only(),
          py::arg("counters") = false, py::arg("trace") = false,
          R"doc(Do clips a and b, placed at pa and pb, ever collide (some samples overlapping in time with
|p_a - p_b| < r_a + r_b)?

a, b    two mobb.Tree (the paper's query), two mobb.ClipIndex (the circle sweep) or two mobb.Clip
        (brute force, the reference); every method gives the same answer.
pa, pb  placements (x, y, theta, t0): metres, metres, radians counter-clockwise, seconds (the start time).
Returns a bool; with counters=True or trace=True a dict: collide, tests2d, tests3d, samples (the
paper's counters, as `mobb query` prints them), pair (a colliding (i, j) or None) and, with trace=True
(trees only), trace: the list of events, each a dict node_a, node_b, test ("time", "box2d", "box3d",
"descend", "samples"), outcome ("no time overlap", "separated", "overlap", "miss", "hit"), sample_a, sample_b, samples_tested.)doc");

    m.def("collide_batch", &collide_batch, py::arg("a"), py::arg("b"), py::arg("placements_a"), py::arg("placements_b"),
          py::kw_only(), py::arg("threads") = 0,
          R"doc(Query k placements of one pair of clips at once: row k asks collide(a, placements_a[k], b,
placements_b[k]).

a, b          as for collide (two Trees, two ClipIndexes or two Clips).
placements_*  (k, 4) float arrays of (x, y, theta, t0): metres, metres, radians, seconds.
threads       worker threads (0: every core). The GIL is released while the queries run.
Returns a (k,) bool array, the same answers as `mobb batch`.)doc");

    m.def("clearance", &clearance_of, py::arg("a"), py::arg("pa"), py::arg("b"), py::arg("pb"),
          R"doc(Clearance over time between placed clips a and b (Clips, Trees, ClipIndexes or (n, 4) path arrays).

Returns a dict of arrays with one entry per sample i of a that overlaps b in time, in time order:
t (global start time of sample i, seconds), gap (smallest |p_a,i - p_b,j| - (r_a,i + r_b,j) over those
samples j of b, metres: negative where the characters collide), i and j (int64 sample indices).
Some gap is negative exactly when collide() is true; the first such t is the first collision time.)doc");
}

}  // namespace mobb::python
