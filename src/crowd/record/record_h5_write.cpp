// Writing a crowd record as HDF5 (the layout in docs/formats.md): the header as attributes of the root,
// the samples by frame blocks, and one group of columns per table, rows in the record's order and tables
// nested by their owner's row (a candidate's "choice", a query's "candidate").
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mobb/crowd/record/record_file.h"
#include "mobb/util/task_queue.h"
#include "record/frame_blocks.h"
#include "record/h5.h"
#include "record/record_json.h"

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

// Tasks waiting for the writer's thread at most: a block of samples holds up to 2 MB (block_frames), a
// table's block up to 4,096 rows of 12 columns, so the queue holds at most some 16 MB; enough for the
// simulation not to wait on a busy disk for a moment. A kill loses what waits here, past the last mark.
constexpr std::size_t kQueued = 8;

using Disks = std::vector<std::array<double, 4>>;

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

// An integer column's type on disk, by what its values can be (docs/formats.md): flags and the outcome
// 8 bits; ids, a candidate's counts and frames 32; row numbers and a choice point's counters (a count of
// pairs grows with the crowd) 64. Most columns are flags and small numbers: narrower, they cost zlib
// and the disk less. HDF5 converts on read, so a reader takes any of them as int64 (ours does).
enum class Bits : std::uint8_t { B8, B32, B64 };

// `rows` as T, every value checked to fit: one that does not is refused, never cut short.
template <class T>
const T* narrowed(const I& rows, std::vector<T>& out, const std::string& path) {
    out.resize(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (rows[k] < std::numeric_limits<T>::min() || rows[k] > std::numeric_limits<T>::max())
            throw h5::Error(path + ": " + std::to_string(rows[k]) + " does not fit in " +
                            std::to_string(8 * sizeof(T)) + " bits");
        out[k] = T(rows[k]);
    }
    return out.data();
}

// A column of integers on disk (one a row), written from int64 rows as its Bits.
class IntColumn {
public:
    IntColumn(hid_t f, const std::string& path, Bits bits)
        : out_(f, path,
               bits == Bits::B8    ? h5::native<std::int8_t>()
               : bits == Bits::B32 ? h5::native<std::int32_t>()
                                   : h5::native<std::int64_t>(),
               kColumn),
          path_(path),
          bits_(bits) {}
    /// Appends `rows` (`b8`, `b32`: scratch).
    void write(const I& rows, std::vector<std::int8_t>& b8, std::vector<std::int32_t>& b32) {
        const void* data = bits_ == Bits::B8    ? static_cast<const void*>(narrowed(rows, b8, path_))
                           : bits_ == Bits::B32 ? static_cast<const void*>(narrowed(rows, b32, path_))
                                                : static_cast<const void*>(rows.data());
        out_.append(data, rows.size(), false);
    }

private:
    h5::Appender out_;
    std::string path_;
    Bits bits_;
};

// A table written as it grows: named columns of integers (one value a row) and float64 (`width` a row,
// not compressed: doubles barely shrink, and deflating them took as many instructions as the rest of the
// writing). The calling thread gathers the rows; the writer's queue writes them, a block at a time.
class Table {
public:
    Table(hid_t f, const std::string& group, std::initializer_list<std::pair<const char*, Bits>> ints,
          std::initializer_list<std::pair<const char*, hsize_t>> reals)
        : ints_(ints.size()), reals_(reals.size()) {
        for (const auto& [name, bits] : ints) int_out_.emplace_back(f, group + "/" + name, bits);
        for (const auto& [name, width] : reals)
            real_out_.emplace_back(f, group + "/" + name, H5T_NATIVE_DOUBLE, h5::Layout{{width}, kColumn.block, false});
    }
    I& i(std::size_t k) { return ints_[k]; }
    D& d(std::size_t k) { return reals_[k]; }
    std::size_t rows() const { return posted_ + ints_[0].size(); }
    /// Hands the rows gathered to `queue` when a block is full (`all`: whatever there is); the file is
    /// flushed by the caller.
    void flush(bool all, util::TaskQueue& queue) {
        if (ints_[0].empty() || (!all && ints_[0].size() < kColumn.block)) return;
        posted_ += ints_[0].size();
        queue.post([this, ints = std::exchange(ints_, std::vector<I>(ints_.size())),
                    reals = std::exchange(reals_, std::vector<D>(reals_.size()))] { write(ints, reals); });
    }

private:
    // On the queue's thread.
    void write(const std::vector<I>& ints, const std::vector<D>& reals) {
        for (std::size_t k = 0; k < ints.size(); ++k) int_out_[k].write(ints[k], b8_, b32_);
        for (std::size_t k = 0; k < reals.size(); ++k) {
            h5::Appender& out = real_out_[k];
            out.append(reals[k].data(), reals[k].size() / h5::row_size(out.layout()), false);
        }
    }

    // Gathered by the calling thread.
    std::vector<I> ints_;
    std::vector<D> reals_;
    std::size_t posted_ = 0;  // rows handed to the queue
    // Touched by the queue's thread alone.
    std::vector<IntColumn> int_out_;
    std::vector<h5::Appender> real_out_;
    std::vector<std::int8_t> b8_;  // scratch: a block narrowed
    std::vector<std::int32_t> b32_;
};

std::int64_t outcome_index(const std::string& outcome) {
    static const char* const kOutcomes[] = {"candidate", "escape", "arrived", "fallback", "right of way"};
    for (std::int64_t k = 0; k < 5; ++k)
        if (outcome == kOutcomes[k]) return k;
    return -1;
}

// The choice points' tables (docs/formats.md): rows appended as choice points come.
struct Tables {
    static constexpr Bits B8 = Bits::B8, B32 = Bits::B32, B64 = Bits::B64;

    explicit Tables(hid_t f)
        : choices(f, "/choices",
                  {{"agent", B32},
                   {"frame", B32},
                   {"taken", B32},
                   {"outcome", B8},
                   {"fallback", B8},
                   {"queries", B64},
                   {"tests2d", B64},
                   {"tests3d", B64},
                   {"samples", B64},
                   {"pruned", B64},
                   {"hold_frame", B32}},
                  {{"hold", 3}}),
          escapes(f, "/escapes", {{"choice", B64}, {"clip", B32}, {"frame", B32}}, {{"place", 3}}),
          intended(f, "/intended", {{"choice", B64}, {"clip", B32}, {"frame", B32}}, {{"place", 3}}),
          reroutes(f, "/reroutes", {{"choice", B64}, {"agent", B32}, {"hold_frame", B32}}, {{"hold", 3}}),
          reroute_escapes(f, "/reroute_escapes", {{"reroute", B64}, {"clip", B32}, {"frame", B32}}, {{"place", 3}}),
          candidates(f, "/candidates",
                     {{"choice", B64},
                      {"clip", B32},
                      {"leaves_world", B8},
                      {"meets_solid", B8},
                      {"queries", B32},
                      {"hits", B32},
                      {"crowded", B8}},
                     {}),
          queries(f, "/queries",
                  {{"candidate", B64}, {"agent", B32}, {"index", B32}, {"piece", B32}, {"mine", B32}, {"hit", B8}}, {}),
          clips(f, "/clips", {{"agent", B32}, {"clip", B32}, {"start", B32}, {"fallback", B8}, {"choice", B64}},
                {{"place", 4}}) {}

    static void framed(Table& t, std::size_t owner, const std::vector<FramedClip>& clips) {
        for (const FramedClip& c : clips) {
            t.i(0).push_back(std::int64_t(owner)), t.i(1).push_back(c.clip), t.i(2).push_back(c.frame);
            t.d(0).insert(t.d(0).end(), {c.place.x, c.place.y, c.place.theta});
        }
    }

    void add(std::size_t c, const ChoicePoint& cp, util::TaskQueue& queue) {
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
        for (Table* t : all()) t->flush(false, queue);
    }

    void add(int agent, const PlacedClip& c, util::TaskQueue& queue) {
        const std::int64_t row[] = {agent, c.clip, c.start, c.fallback, c.choice};
        for (std::size_t k = 0; k < std::size(row); ++k) clips.i(k).push_back(row[k]);
        clips.d(0).insert(clips.d(0).end(), {c.place.x, c.place.y, c.place.theta, c.place.t0});
        clips.flush(false, queue);
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
    std::mutex spare_mutex;
    std::vector<Disks> spare;  // blocks of samples written, their memory used again
    // Between begin() and finish() the file is written here alone (HDF5's serial library is not to be
    // called from two threads at once), in the order the calls came; last, so that it goes first, once
    // what it holds is written.
    util::TaskQueue queue{kQueued};

    // Every table's rows so far, then the mark: the frames a reader may take, and each table's rows.
    void mark() {
        std::vector<std::int64_t> written{frames};
        for (Table* t : tables->all()) t->flush(true, queue), written.push_back(std::int64_t(t->rows()));
        queue.post([this, written] {
            h5::write_numbers<std::int64_t>(f.get(), "written", written);
            if (H5Fflush(f.get(), H5F_SCOPE_GLOBAL) < 0) throw h5::Error("cannot write");
        });
        marked = frames;
    }

    // A block of samples to the queue, copied: the stream uses its own again.
    void append(const FrameBlock& block) {
        Disks disks;
        {
            const std::lock_guard<std::mutex> lock(spare_mutex);
            if (!spare.empty()) disks = std::move(spare.back()), spare.pop_back();
        }
        disks.assign(block.disks, block.disks + std::ptrdiff_t(block.count * std::int64_t(agents)));
        queue.post([this, disks = std::move(disks), count = block.count]() mutable {
            samples->append(disks.data(), hsize_t(count), false);
            const std::lock_guard<std::mutex> lock(spare_mutex);
            spare.push_back(std::move(disks));
        });
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
        impl_->queue.drain();
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
        impl_->tables->add(index, choice, impl_->queue);
        ++impl_->choices;
    });
}

void H5RecordWriter::clip(int agent, const PlacedClip& clip) {
    guarded(impl_->file, [&] { impl_->tables->add(agent, clip, impl_->queue); });
}

void H5RecordWriter::frames(const FrameBlock& block) {
    guarded(impl_->file, [&] {
        if (!impl_->samples || block.first != impl_->frames || block.agents != impl_->agents)
            throw h5::Error("/tracks/samples: frames " + std::to_string(block.first) + " sent out of order");
        impl_->append(block);
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
        impl_->queue.drain();  // the file is this thread's again
        const hid_t f = impl_->f.get();
        Record named;
        named.graph = r.graph.empty() ? impl_->graph : r.graph;
        named.scenario = r.scenario.empty() ? impl_->scenario : r.scenario;
        write_header(f, r, named, summary_json, metrics_json);
        write_left(f, r);
        impl_->mark();
        impl_->queue.drain();
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
