// Writing a crowd record as HDF5 (the layout in docs/formats.md): the header as attributes of the root,
// the samples by frame blocks, and one group of columns per table, rows in the record's order and tables
// nested by their owner's row (a candidate's "choice", a query's "candidate").
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <utility>

#include "frame_stream.h"
#include "h5.h"
#include "mobb/crowd/record_file.h"
#include "record_json.h"

namespace mobb::crowd {

namespace {

using I = std::vector<std::int64_t>;
using D = std::vector<double>;
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
const h5::Layout kColumn{};
const h5::Layout kPair{{2}}, kTriple{{3}}, kPlace{{4}};

// A streamed file is marked readable (its "written" attribute) after a block of samples once this many
// frames went out since the last mark: each mark writes every table's last, partial block again
// (compressed), so marking every block of a large crowd (6 frames at 10,000 agents) would cost more than
// it saves. 30 frames: one second of a 30 fps graph is what a killed run loses at most.
constexpr std::int64_t kMarkFrames = 30;

// The root's attributes; the graph and the scenario from `names`.
void write_header(hid_t f, const Record& r, const Record& names, const std::string& summary,
                  const std::string& metrics) {
    h5::write_text(f, "format", "mobb crowd record");
    h5::write_numbers<std::int64_t>(f, "version", {kRecordVersion});
    h5::write_text(f, "graph", names.graph);
    h5::write_numbers<double>(f, "dt", {r.dt});
    h5::write_numbers<std::int64_t>(f, "frames", {r.frames});
    h5::write_numbers<std::int64_t>(f, "agents", {std::int64_t(r.tracks.size())});
    h5::write_numbers<std::uint64_t>(f, "seed", {r.seed});
    h5::write_text(f, "tree", r.tree);
    h5::write_text(f, "select", r.select);
    if (!names.scenario.empty()) h5::write_text(f, "scenario", names.scenario);
    h5::write_numbers<double>(f, "world", {r.world.x0, r.world.y0, r.world.x1, r.world.y1});
    h5::write_numbers<std::int64_t>(f, "walls", {r.world.walls});
    h5::write_text(f, "summary", summary.empty() ? "{}" : summary);
    if (!metrics.empty()) h5::write_text(f, "metrics", metrics);
}

void write_obstacles(hid_t f, const World& w) {
    I polygon;
    D vertex;
    for (std::size_t k = 0; k < w.obstacles.size(); ++k)
        for (const auto& v : w.obstacles[k].vertices)
            polygon.push_back(std::int64_t(k)), vertex.insert(vertex.end(), {v[0], v[1]});
    h5::write_rows(f, "/obstacles/polygon", polygon, kColumn);
    h5::write_rows(f, "/obstacles/vertex", vertex, kPair);
}

// What is known of the agents before the run: their goals and what they do at the last.
void write_goals(hid_t f, const Record& r) {
    I at_goal, goal_agent;
    D goal;
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        const AgentTrack& t = r.tracks[a];
        at_goal.push_back(t.at_goal == AtGoal::Leave);
        for (const auto& g : t.goals) goal_agent.push_back(std::int64_t(a)), goal.insert(goal.end(), {g[0], g[1]});
    }
    h5::write_rows(f, "/tracks/at_goal", at_goal, kColumn);
    h5::write_rows(f, "/goals/agent", goal_agent, kColumn);
    h5::write_rows(f, "/goals/xy", goal, kPair);
}

void write_left(hid_t f, const Record& r) {
    I left;
    for (const AgentTrack& t : r.tracks) left.push_back(t.left_frame.value_or(-1));
    h5::write_rows(f, "/tracks/left_frame", left, kColumn);
}

// A table written as it grows: named columns of int64 (one value a row) and float64 (`width` a row),
// appended a block of rows at a time.
class Table {
public:
    Table(hid_t f, const std::string& group, std::initializer_list<const char*> ints,
          std::initializer_list<std::pair<const char*, hsize_t>> reals) {
        for (const char* name : ints)
            ints_.emplace_back(h5::Appender(f, group + "/" + name, H5T_NATIVE_INT64, kColumn), I{});
        for (const auto& [name, width] : reals)
            reals_.emplace_back(h5::Appender(f, group + "/" + name, H5T_NATIVE_DOUBLE, h5::Layout{{width}}), D{});
    }
    I& i(std::size_t k) { return ints_[k].second; }
    D& d(std::size_t k) { return reals_[k].second; }
    std::size_t rows() const { return std::size_t(ints_[0].first.rows()) + ints_[0].second.size(); }
    /// Writes the rows gathered when a block is full (`all`: whatever there is); the file is flushed by
    /// the caller.
    void flush(bool all) {
        if (!all && ints_[0].second.size() < kColumn.block) return;
        for (auto& [out, rows] : ints_) out.append(rows.data(), rows.size(), false), rows.clear();
        for (auto& [out, rows] : reals_)
            out.append(rows.data(), rows.size() / h5::row_size(out.layout()), false), rows.clear();
    }

private:
    std::vector<std::pair<h5::Appender, I>> ints_;
    std::vector<std::pair<h5::Appender, D>> reals_;
};

std::int64_t outcome_index(const std::string& outcome) {
    static const char* const kOutcomes[] = {"candidate", "escape", "arrived", "fallback", "right of way"};
    for (std::int64_t k = 0; k < 5; ++k)
        if (outcome == kOutcomes[k]) return k;
    return -1;
}

// The choice points' tables (docs/formats.md): rows appended as choice points come.
struct Tables {
    explicit Tables(hid_t f)
        : choices(f, "/choices",
                  {"agent", "frame", "taken", "outcome", "fallback", "queries", "tests2d", "tests3d", "samples",
                   "pruned", "hold_frame"},
                  {{"hold", 3}}),
          escapes(f, "/escapes", {"choice", "clip", "frame"}, {{"place", 3}}),
          intended(f, "/intended", {"choice", "clip", "frame"}, {{"place", 3}}),
          reroutes(f, "/reroutes", {"choice", "agent", "hold_frame"}, {{"hold", 3}}),
          reroute_escapes(f, "/reroute_escapes", {"reroute", "clip", "frame"}, {{"place", 3}}),
          candidates(f, "/candidates", {"choice", "clip", "leaves_world", "meets_solid", "queries", "hits", "crowded"},
                     {}),
          queries(f, "/queries", {"candidate", "agent", "index", "piece", "mine", "hit"}, {}),
          clips(f, "/clips", {"agent", "clip", "start", "fallback", "choice"}, {{"place", 4}}) {}

    static void framed(Table& t, std::size_t owner, const std::vector<FramedClip>& clips) {
        for (const FramedClip& c : clips) {
            t.i(0).push_back(std::int64_t(owner)), t.i(1).push_back(c.clip), t.i(2).push_back(c.frame);
            t.d(0).insert(t.d(0).end(), {c.place.x, c.place.y, c.place.theta});
        }
    }

    void add(std::size_t c, const ChoicePoint& cp) {
        const std::int64_t row[] = {cp.agent,
                                    cp.frame,
                                    cp.taken,
                                    outcome_index(cp.outcome),
                                    cp.fallback,
                                    std::int64_t(cp.queries),
                                    std::int64_t(cp.tests2d),
                                    std::int64_t(cp.tests3d),
                                    std::int64_t(cp.samples),
                                    std::int64_t(cp.pruned),
                                    cp.holds ? cp.hold_frame : -1};
        for (std::size_t k = 0; k < std::size(row); ++k) choices.i(k).push_back(row[k]);
        for (std::size_t k = 0; k < 3; ++k) choices.d(0).push_back(cp.holds ? cp.hold[k] : kNone);
        framed(escapes, c, cp.escape);
        framed(intended, c, cp.intended);
        for (const ReroutedPlan& p : cp.reroutes) {
            framed(reroute_escapes, reroutes.rows(), p.escape);
            reroutes.i(0).push_back(std::int64_t(c)), reroutes.i(1).push_back(p.agent),
                reroutes.i(2).push_back(p.hold_frame);
            reroutes.d(0).insert(reroutes.d(0).end(), p.hold.begin(), p.hold.end());
        }
        for (const Candidate& k : cp.candidates) {
            for (const CandidateQuery& q : k.against) {
                const std::int64_t r[] = {
                    std::int64_t(candidates.rows()), q.agent, query_index(q), q.piece, q.mine, q.hit};
                for (std::size_t j = 0; j < 6; ++j) queries.i(j).push_back(r[j]);
            }
            const std::int64_t r[] = {std::int64_t(c), k.clip, k.leaves_world, k.meets_solid,
                                      k.queries,       k.hits, k.crowded};
            for (std::size_t j = 0; j < std::size(r); ++j) candidates.i(j).push_back(r[j]);
        }
        for (Table* t : all()) t->flush(false);
    }

    void add(int agent, const PlacedClip& c) {
        const std::int64_t row[] = {agent, c.clip, c.start, c.fallback, c.choice};
        for (std::size_t k = 0; k < std::size(row); ++k) clips.i(k).push_back(row[k]);
        clips.d(0).insert(clips.d(0).end(), {c.place.x, c.place.y, c.place.theta, c.place.t0});
        clips.flush(false);
    }

    /// In the order of the "written" attribute (docs/formats.md).
    std::array<Table*, 8> all() {
        return {&choices, &clips, &escapes, &intended, &reroutes, &reroute_escapes, &candidates, &queries};
    }

    Table choices, escapes, intended, reroutes, reroute_escapes, candidates, queries, clips;
};

}  // namespace

struct H5RecordWriter::Impl {
    std::string file, graph, scenario;
    h5::Id f;
    std::unique_ptr<Tables> tables;
    std::optional<h5::Appender> samples;  // from begin()
    std::size_t agents = 0, choices = 0;
    std::int64_t frames = 0, marked = 0;  // frames written; at the last mark

    // Every table's rows so far, then the mark: the frames a reader may take, and each table's rows.
    void mark() {
        std::vector<std::int64_t> written{frames};
        for (Table* t : tables->all()) t->flush(true), written.push_back(std::int64_t(t->rows()));
        h5::write_numbers<std::int64_t>(f.get(), "written", written);
        if (H5Fflush(f.get(), H5F_SCOPE_GLOBAL) < 0) throw h5::Error("cannot write");
        marked = frames;
    }
};

namespace {

// Runs `write`, an h5::Error becoming "FILE: PLACE: message".
template <class F>
void guarded(const std::string& file, F&& write) {
    try {
        write();
    } catch (const h5::Error& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

}  // namespace

H5RecordWriter::H5RecordWriter(const std::string& file, const std::string& graph, const std::string& scenario)
    : impl_(std::make_unique<Impl>()) {
    h5::quiet();
    impl_->file = file;
    impl_->graph = graph;
    impl_->scenario = scenario;
    guarded(file, [&] {
        // Space a block held is never given to another while the file is written: a table's last block is
        // written again, larger, at each mark, and the file as of the last mark points at the old copy -
        // which a kill before the next flush would otherwise find overwritten.
        const h5::Id fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
        H5Pset_file_space_strategy(fcpl.get(), H5F_FSPACE_STRATEGY_NONE, 0, 1);
        impl_->f = h5::Id(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), H5Fclose);
        if (!impl_->f.valid()) throw h5::Error("cannot create");
        h5::write_numbers<std::int64_t>(impl_->f.get(), "complete", {0});
        impl_->tables = std::make_unique<Tables>(impl_->f.get());
    });
}

H5RecordWriter::~H5RecordWriter() = default;

void H5RecordWriter::begin(const Record& header) {
    guarded(impl_->file, [&] {
        if (impl_->samples) throw h5::Error("begun twice");
        Record named;  // the names the writer was given, where the header has none
        named.graph = header.graph.empty() ? impl_->graph : header.graph;
        named.scenario = header.scenario.empty() ? impl_->scenario : header.scenario;
        const hid_t f = impl_->f.get();
        write_header(f, header, named, "", "");
        write_obstacles(f, header.world);
        write_goals(f, header);
        impl_->agents = header.tracks.size();
        const h5::Layout layout{{hsize_t(impl_->agents), 4}, hsize_t(block_frames(impl_->agents)), false};
        impl_->samples.emplace(f, "/tracks/samples", H5T_NATIVE_DOUBLE, layout);
        impl_->mark();
    });
}

void H5RecordWriter::choice(std::size_t index, const ChoicePoint& choice) {
    guarded(impl_->file, [&] {
        if (index != impl_->choices) throw h5::Error("choice point " + std::to_string(index) + " sent out of order");
        impl_->tables->add(index, choice);
        ++impl_->choices;
    });
}

void H5RecordWriter::clip(int agent, const PlacedClip& clip) {
    guarded(impl_->file, [&] { impl_->tables->add(agent, clip); });
}

void H5RecordWriter::frames(const FrameBlock& block) {
    guarded(impl_->file, [&] {
        if (!impl_->samples || block.first != impl_->frames || block.agents != impl_->agents)
            throw h5::Error("/tracks/samples: frames " + std::to_string(block.first) + " sent out of order");
        impl_->samples->append(block.disks->data(), hsize_t(block.count), false);
        impl_->frames += block.count;
        if (impl_->frames - impl_->marked >= kMarkFrames) impl_->mark();
    });
}

void H5RecordWriter::finish(const Record& r, const std::string& summary_json, const std::string& metrics_json) {
    guarded(impl_->file, [&] {
        if (!impl_->samples) throw h5::Error("finished before it began");
        if (!r.choices.empty() && impl_->choices != r.choices.size())
            throw h5::Error(std::to_string(impl_->choices) + " choice points sent, the record has " +
                            std::to_string(r.choices.size()));
        if (impl_->frames != r.frames)
            throw h5::Error("/tracks/samples: " + std::to_string(impl_->frames) + " frames sent, the record has " +
                            std::to_string(r.frames));
        const hid_t f = impl_->f.get();
        Record named;
        named.graph = r.graph.empty() ? impl_->graph : r.graph;
        named.scenario = r.scenario.empty() ? impl_->scenario : r.scenario;
        write_header(f, r, named, summary_json, metrics_json);
        write_left(f, r);
        impl_->mark();
        // Last: a reader tells a finished file from one whose writing stopped (killed, disk full).
        const h5::Id done(H5Aopen(f, "complete", H5P_DEFAULT), H5Aclose);
        const std::int64_t one = 1;
        if (H5Awrite(done.get(), H5T_NATIVE_INT64, &one) < 0 || H5Fflush(f, H5F_SCOPE_GLOBAL) < 0)
            throw h5::Error("cannot write");
    });
}

void write_h5_record(const std::string& file, const Record& r, const std::string& summary_json,
                     const std::string& metrics_json) {
    H5RecordWriter out(file);
    out.begin(r);
    for (std::size_t c = 0; c < r.choices.size(); ++c) out.choice(c, r.choices[c]);
    // The clips in commit order, as a streamed run sends them (each choice point commits one).
    std::vector<std::pair<int, const PlacedClip*>> clips;
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (const PlacedClip& c : r.tracks[a].clips) clips.emplace_back(int(a), &c);
    std::stable_sort(clips.begin(), clips.end(),
                     [](const auto& x, const auto& y) { return x.second->choice < y.second->choice; });
    for (const auto& [agent, c] : clips) out.clip(agent, *c);
    const std::size_t n = r.tracks.size();
    const std::int64_t block = block_frames(n);
    std::vector<std::array<double, 4>> disks(std::size_t(block) * n);
    for (std::int64_t first = 0; first < r.frames; first += block) {
        FrameBlock b;
        b.first = first;
        b.count = std::min(block, r.frames - first);
        b.agents = n;
        b.disks = disks.data();
        for (std::int64_t k = 0; k < b.count; ++k)
            for (std::size_t a = 0; a < n; ++a) {
                const auto& s = r.tracks[a].samples;
                const auto f = std::size_t(first + k);
                disks[std::size_t(k) * n + a] = f < s.size() ? s[f] : std::array<double, 4>{kNone, kNone, kNone, kNone};
            }
        out.frames(b);
    }
    out.finish(r, summary_json, metrics_json);
}

}  // namespace mobb::crowd
