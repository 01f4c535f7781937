// Table 1 (tables.h): the crowd's own narrow-phase queries replayed by every method, and frame stepping
// on the same choice points.
#include <algorithm>
#include <stdexcept>

#include "frame_stepping.h"
#include "machine.h"
#include "mobb/crowd/sim/crowd.h"
#include "mobb/util/json_text.h"
#include "tables.h"
#include "workloads.h"

namespace mobb::bench {

namespace {

using util::fixed;

crowd::CrowdOptions crowd_options(const Table1Options& o) {
    crowd::CrowdOptions co;
    co.agents = o.agents;
    co.world.x1 = o.width;
    co.world.y1 = o.height;
    co.seconds = o.seconds;
    co.seed = o.seed;
    co.select = crowd::Selection::Random;
    co.log_queries = true;
    return co;
}

// The crowd's CD time as a crowd spends it: the same run (same choice points) without the query log and
// the candidates' query lists, bookkeeping for this table that cd_seconds would time too.
crowd::CrowdSummary unrecorded_run(const crowd::MotionGraph& g, const crowd::NarrowPhase& narrow,
                                   const Table1Options& o) {
    crowd::CrowdOptions co = crowd_options(o);
    co.log_queries = false;
    co.record_queries = false;
    return crowd::run_crowd(g, narrow, co).summary;
}

// The crowd-against-frame-stepping target is per simulated second, on the choice points of this run
// (the crowd's own CD time, CrowdSummary::cd_seconds of the unrecorded run).
Target stepping_target(const BenchTable& t, const crowd::CrowdSummary& s, const FrameSteppingResult& fs,
                       double seconds) {
    Target g;
    g.what = "crowd CD time per simulated second >= 10x less than frame stepping on the same choice points";
    g.goal = 10;
    const double step = (fs.build_seconds + fs.check_seconds) / seconds;
    const MethodRow* m = find_row(t.rows, Method::Sweep);
    const double replay = m ? m->us_per_query * 1e-6 * double(m->queries) / seconds : 0;
    g.detail = "frame stepping " + fixed(step * 1e3, 3) + " ms per simulated s; crowd cd_seconds " +
               fixed(s.cd_seconds / seconds * 1e3, 3) +
               " ms per simulated s; circle sweep replay of the same queries " + fixed(replay * 1e3, 3) +
               " ms per simulated s (narrow phase only, " + fixed(replay > 0 ? step / replay : 0, 1) + "x)";
    if (s.cd_seconds > 0) {
        g.measured = step / (s.cd_seconds / seconds);
    } else {
        g.known = false;
        g.detail = "CrowdSummary::cd_seconds reads 0; " + g.detail;
    }
    return g;
}

MethodRow stepping_row(const BenchTable& t, const FrameSteppingResult& fs, std::size_t queries) {
    MethodRow step;
    step.label = "frame stepping";
    step.queries = queries;
    const double nq = double(std::max<std::size_t>(1, queries));
    step.us_per_query = (fs.build_seconds + fs.check_seconds) * 1e6 / nq;
    step.samples = double(fs.disk_tests) / nq;
    step.positive = fs.candidates ? double(fs.positive) / double(fs.candidates) : 0.0;
    step.disagreements = fs.disagreements;
    step.extra = fs.only_stepping;
    step.missed = fs.only_queries;
    step.note = "per candidate, not per query; time = (grid build + stepping) / queries";
    step.timed_queries = step.queries;
    if (const MethodRow* m = find_row(t.rows, Method::Sweep)) step.x_sweep = step.us_per_query / m->us_per_query;
    return step;
}

void add_notes(BenchTable& t, const Table1Options& o, const crowd::MotionGraph& g, const crowd::CrowdRun& run,
               const std::vector<Tree>& trees, const QuerySet& set, const FrameSteppingResult& fs) {
    double clip_seconds = 0;
    for (const crowd::GraphClip& c : g.clips) clip_seconds += c.path.duration();
    const crowd::CrowdSummary& s = run.summary;
    const double nq = double(std::max<std::size_t>(1, set.queries.size()));
    const double choices = double(std::max<std::uint64_t>(1, s.choice_points));
    t.notes["graph"] = o.graph + " (" + std::to_string(g.clips.size()) + " clips, mean " +
                       fixed(clip_seconds / double(g.clips.size()), 2) + " s, dt 1/" + fixed(g.fps, 0) + " s)";
    t.notes["crowd"] = std::to_string(o.agents) + " agents, " + fixed(o.width, 0) + " x " + fixed(o.height, 0) +
                       " m, " + fixed(o.seconds, 0) + " s, seed " + std::to_string(o.seed) +
                       ", random selection, n_min " + std::to_string(o.n_min);
    t.notes["choice points"] = std::to_string(s.choice_points) + " (" + std::to_string(s.candidates) + " candidates)";
    t.notes["queries"] = std::to_string(set.queries.size()) + " (every row answers these same queries)";
    t.notes["rejected at the root (MOBB)"] = fixed(100.0 * double(s.root_rejected) / nq, 1) + " %";
    t.notes["root overlap share (MOBB root boxes)"] = fixed(100.0 * root_share(trees, set.queries), 1) + " %";
    t.notes["broad phase"] = std::to_string(s.pruned) + " of " + std::to_string(s.time_pairs) +
                             " time-overlapping pairs pruned before any query";
    t.notes["frame stepping"] = std::to_string(fs.candidates) + " candidates, grid build " +
                                fixed(fs.build_seconds * 1e3, 2) + " ms, stepping " + fixed(fs.check_seconds * 1e3, 2) +
                                " ms, " + std::to_string(fs.disk_tests) + " disk tests, " +
                                std::to_string(fs.disagreements) + " answers differing from the queries' (" +
                                std::to_string(fs.only_queries) + " positive by the queries only, " +
                                std::to_string(fs.only_stepping) + " by stepping only)";
    t.notes["crowd simulation (MOBB queries, broad phase, bookkeeping)"] =
        fixed(s.seconds * 1e3, 1) + " ms, " + fixed(s.seconds * 1e6 / choices, 2) + " us per choice point";
    if (const MethodRow* mobb = find_row(t.rows, Method::Mobb))
        t.notes["tree time per choice point (MOBB)"] = fixed(mobb->us_per_query * nq / choices, 2) + " us";
    t.notes["frame stepping time per choice point"] =
        fixed((fs.build_seconds + fs.check_seconds) * 1e6 / choices, 2) + " us";
    t.notes["passes"] = std::to_string(o.passes);
    add_machine_notes(t.notes);
}

}  // namespace

BenchTable run_table1(const Table1Options& o, const std::function<void(double)>& progress) {
    const crowd::MotionGraph g = crowd::load_graph(o.graph);
    const crowd::NarrowPhase narrow = crowd::NarrowPhase::trees(g, {TreeType::Mobb, o.n_min});
    const std::vector<Tree>& trees = narrow.tree_list();
    const crowd::CrowdRun run = crowd::run_crowd(g, narrow, crowd_options(o), progress_stage(progress, 0.0, 0.05));
    const crowd::CrowdSummary unrecorded = unrecorded_run(g, narrow, o);
    if (unrecorded.choice_points != run.summary.choice_points)  // recording must not change the run
        throw std::logic_error("table1: the crowd without a record took other choice points");
    if (progress) progress(0.1);
    const QuerySet set = crowd_query_set(g, run.queries);
    if (!o.save_queries.empty()) save_query_set(set, o.save_queries);

    BenchTable t;
    t.workload = "table1";
    t.title = "Table 1: crowd workload (" + std::to_string(o.agents) + " agents, " + fixed(o.width, 0) + " x " +
              fixed(o.height, 0) + " m, " + fixed(o.seconds, 0) + " s, random selection)";
    t.rows = time_methods(set, make_methods(table_methods(), o.n_min), o.passes, progress_stage(progress, 0.1, 0.95),
                          o.slow_queries);
    const FrameSteppingResult fs = frame_stepping(g, run.record);
    t.rows.push_back(stepping_row(t, fs, set.queries.size()));
    if (progress) progress(1.0);
    t.targets.push_back(speed_target(t.rows, Method::Scan, 1));
    t.targets.push_back(speed_target(t.rows, Method::Mobb1, 4));
    t.targets.push_back(stepping_target(t, unrecorded, fs, o.seconds));
    add_notes(t, o, g, run, trees, set, fs);  // the trees are MOBB trees of the set's clips
    t.notes["crowd CD time without the query log and candidate record (the target's)"] =
        fixed(unrecorded.cd_seconds * 1e3, 1) + " ms, against " + fixed(run.summary.cd_seconds * 1e3, 1) +
        " ms recorded";
    return t;
}

}  // namespace mobb::bench
