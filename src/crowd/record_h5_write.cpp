// Writing a crowd record as HDF5 (the layout in docs/formats.md): the header as attributes of the root,
// the samples by frame blocks, and one group of columns per table, rows in the record's order and tables
// nested by their owner's row (a candidate's "choice", a query's "candidate").
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

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

// Frames per block of samples: about 64 k disks (2 MB) a block, 1 to 256 frames.
hsize_t block_frames(std::size_t agents) {
    return hsize_t(std::clamp<std::size_t>(65536 / std::max<std::size_t>(1, agents), 1, 256));
}

void write_header(hid_t f, const Record& r, const std::string& summary, const std::string& metrics) {
    h5::write_text(f, "format", "mobb crowd record");
    h5::write_numbers<std::int64_t>(f, "version", {2});
    h5::write_text(f, "graph", r.graph);
    h5::write_numbers<double>(f, "dt", {r.dt});
    h5::write_numbers<std::int64_t>(f, "frames", {r.frames});
    h5::write_numbers<std::int64_t>(f, "agents", {std::int64_t(r.tracks.size())});
    h5::write_numbers<std::uint64_t>(f, "seed", {r.seed});
    h5::write_text(f, "tree", r.tree);
    h5::write_text(f, "select", r.select);
    if (!r.scenario.empty()) h5::write_text(f, "scenario", r.scenario);
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

void write_tracks(hid_t f, const Record& r) {
    I left, at_goal, goal_agent, agent, clip, start, fallback, commit;
    D goal, place;
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        const AgentTrack& t = r.tracks[a];
        left.push_back(t.left_frame.value_or(-1));
        at_goal.push_back(t.at_goal == AtGoal::Leave);
        for (const auto& g : t.goals) goal_agent.push_back(std::int64_t(a)), goal.insert(goal.end(), {g[0], g[1]});
        for (const PlacedClip& c : t.clips) {
            agent.push_back(std::int64_t(a)), clip.push_back(c.clip), start.push_back(c.start);
            fallback.push_back(c.fallback), commit.push_back(c.commit);
            place.insert(place.end(), {c.place.x, c.place.y, c.place.theta, c.place.t0});
        }
    }
    h5::write_rows(f, "/tracks/left_frame", left, kColumn);
    h5::write_rows(f, "/tracks/at_goal", at_goal, kColumn);
    h5::write_rows(f, "/goals/agent", goal_agent, kColumn);
    h5::write_rows(f, "/goals/xy", goal, kPair);
    for (const auto& [name, column] :
         {std::pair{"agent", &agent}, {"clip", &clip}, {"start", &start}, {"fallback", &fallback}, {"commit", &commit}})
        h5::write_rows(f, std::string("/clips/") + name, *column, kColumn);
    h5::write_rows(f, "/clips/place", place, kPlace);
}

// [frames, agents, 4]: agent a's disk [t, x, y, r] at frame k, NaN once it left.
void write_samples(hid_t f, const Record& r) {
    const std::size_t n = r.tracks.size();
    const h5::Layout layout{{hsize_t(n), 4}, block_frames(n), false};
    h5::write_rows<double>(f, "/tracks/samples", hsize_t(r.frames), layout,
                           [&](hsize_t first, hsize_t count, double* out) {
                               for (hsize_t k = first; k < first + count; ++k)
                                   for (std::size_t a = 0; a < n; ++a, out += 4) {
                                       const auto& s = r.tracks[a].samples;
                                       if (k < s.size())
                                           std::copy(s[k].begin(), s[k].end(), out);
                                       else
                                           std::fill(out, out + 4, kNone);
                                   }
                           });
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
    /// Writes the rows gathered when a block is full (`all`: whatever there is).
    void flush(bool all) {
        if (!all && ints_[0].second.size() < kColumn.block) return;
        for (auto& [out, rows] : ints_) out.append(rows.data(), rows.size()), rows.clear();
        for (auto& [out, rows] : reals_)
            out.append(rows.data(), rows.size() / h5::row_size(out.layout())), rows.clear();
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
          candidates(f, "/candidates", {"choice", "clip", "outside", "queries", "hits", "crowded"}, {}),
          queries(f, "/queries", {"candidate", "agent", "commit", "piece", "mine", "hit"}, {}) {}

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
                const std::int64_t r[] = {std::int64_t(candidates.rows()), q.agent, q.commit, q.piece, q.mine, q.hit};
                for (std::size_t j = 0; j < 6; ++j) queries.i(j).push_back(r[j]);
            }
            const std::int64_t r[] = {std::int64_t(c), k.clip, k.outside, k.queries, k.hits, k.crowded};
            for (std::size_t j = 0; j < 6; ++j) candidates.i(j).push_back(r[j]);
        }
        for (Table* t : all()) t->flush(false);
    }

    std::array<Table*, 7> all() {
        return {&choices, &escapes, &intended, &reroutes, &reroute_escapes, &candidates, &queries};
    }

    Table choices, escapes, intended, reroutes, reroute_escapes, candidates, queries;
};

}  // namespace

struct H5RecordWriter::Impl {
    std::string file;
    h5::Id f;
    std::unique_ptr<Tables> tables;
    std::size_t choices = 0;
};

H5RecordWriter::H5RecordWriter(const std::string& file) : impl_(std::make_unique<Impl>()) {
    h5::quiet();
    impl_->file = file;
    try {
        impl_->f = h5::Id(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
        if (!impl_->f.valid()) throw h5::Error("cannot create");
        h5::write_numbers<std::int64_t>(impl_->f.get(), "complete", {0});
        impl_->tables = std::make_unique<Tables>(impl_->f.get());
    } catch (const h5::Error& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

H5RecordWriter::~H5RecordWriter() = default;

void H5RecordWriter::choice(std::size_t index, const ChoicePoint& choice) {
    try {
        if (index != impl_->choices) throw h5::Error("choice point " + std::to_string(index) + " sent out of order");
        impl_->tables->add(index, choice);
        ++impl_->choices;
    } catch (const h5::Error& e) {
        throw std::runtime_error(impl_->file + ": " + e.what());
    }
}

void H5RecordWriter::finish(const Record& r, const std::string& summary_json, const std::string& metrics_json) {
    try {
        if (impl_->choices != r.choices.size())
            throw h5::Error(std::to_string(impl_->choices) + " choice points sent, the record has " +
                            std::to_string(r.choices.size()));
        for (Table* t : impl_->tables->all()) t->flush(true);
        const hid_t f = impl_->f.get();
        write_header(f, r, summary_json, metrics_json);
        write_obstacles(f, r.world);
        write_tracks(f, r);
        write_samples(f, r);
        // Last: a reader tells a finished file from one whose writing stopped (killed, disk full).
        const h5::Id done(H5Aopen(f, "complete", H5P_DEFAULT), H5Aclose);
        const std::int64_t one = 1;
        if (H5Awrite(done.get(), H5T_NATIVE_INT64, &one) < 0 || H5Fflush(f, H5F_SCOPE_GLOBAL) < 0)
            throw h5::Error("cannot write");
    } catch (const h5::Error& e) {
        throw std::runtime_error(impl_->file + ": " + e.what());
    }
}

void write_h5_record(const std::string& file, const Record& r, const std::string& summary_json,
                     const std::string& metrics_json) {
    H5RecordWriter out(file);
    for (std::size_t c = 0; c < r.choices.size(); ++c) out.choice(c, r.choices[c]);
    out.finish(r, summary_json, metrics_json);
}

}  // namespace mobb::crowd
