// Table 2 (tables.h): identical random tests on long motions, every method; and the workloads by name.
#include <stdexcept>

#include "machine.h"
#include "mobb/crowd/sim/crowd.h"
#include "mobb/util/json_text.h"
#include "tables.h"
#include "workloads.h"

namespace mobb::bench {

namespace {

using util::fixed;

std::vector<NamedPath> table2_motions(const Table2Options& o) {
    if (!o.synth) return longest_clips(o.motions, o.fps);
    return graph_walks(crowd::load_graph(o.graph), o.motions, o.synth_seconds, o.seed ^ 0x5eedull);
}

// The share of root overlaps among the queries of a crowd run (random selection, 30 x 40 m).
double crowd_root_share(const Table2Options& o, std::string& source) {
    const crowd::MotionGraph g = crowd::load_graph(o.graph);
    crowd::CrowdOptions co;
    co.agents = o.crowd_agents;
    co.seconds = o.crowd_seconds;
    co.seed = o.seed;
    co.select = crowd::Selection::Random;
    co.log_queries = true;
    const crowd::NarrowPhase narrow = crowd::NarrowPhase::trees(g, {});
    const QuerySet set = crowd_query_set(g, crowd::run_crowd(g, narrow, co).queries);
    const std::vector<Tree>& trees = narrow.tree_list();
    source = "measured on a crowd run (" + std::to_string(co.agents) + " agents, 30 x 40 m, " + fixed(co.seconds, 0) +
             " s, random selection, " + std::to_string(set.queries.size()) + " queries)";
    return root_share(trees, set.queries);
}

void add_targets(BenchTable& t, const Table2Options& o) {
    if (!o.synth) {
        t.targets.push_back(speed_target(t.rows, Method::Scan, 1));
        t.targets.push_back(speed_target(t.rows, Method::Mobb1, 25));
        t.targets.push_back(speed_target(t.rows, Method::Fcl, 20));
    } else {
        t.targets.push_back(speed_target(t.rows, Method::Scan, o.synth_seconds >= 100 ? 8 : 2));
    }
}

void add_notes(BenchTable& t, const Table2Options& o, const QuerySet& set, const Table2Setup& setup) {
    std::string names;
    for (std::size_t k = 0; k < set.clips.size(); ++k)
        names += (names.empty() ? "" : ", ") + setup.names[k] + " (" + fixed(set.clips[k].duration(), 1) + " s)";
    t.notes["motions"] = names;
    t.notes["sampling"] = "dt 1/" + fixed(o.fps, 0) + " s";
    t.notes["root overlap target"] = fixed(100.0 * setup.target, 1) + " %, " + setup.target_source;
    t.notes["root overlap achieved"] = fixed(100.0 * setup.achieved, 1) + " % (MOBB root boxes, all tests)";
    t.notes["translation radius"] = fixed(setup.radius, 3) + " m (uniform disk about the first motion's centre)";
    t.notes["rotation, time offset"] =
        "uniform in [-pi, pi); uniform over the offsets where the motions overlap in time";
    t.notes["passes"] = std::to_string(o.passes);
    t.notes["seed"] = std::to_string(o.seed);
    add_machine_notes(t.notes);
}

}  // namespace

QuerySet table2_query_set(const Table2Options& o, Table2Setup* setup) {
    Table2Setup local;
    Table2Setup& s = setup ? *setup : local;
    QuerySet set;
    for (NamedPath& m : table2_motions(o)) {
        s.names.push_back(m.name);
        set.clips.push_back(std::move(m.path));
    }
    if (set.clips.empty()) throw std::runtime_error("table2: no motions");
    const std::vector<Tree> roots = mobb_trees(set.clips, o.n_min);
    s.target = o.root_share;
    s.target_source = "given";
    if (s.target < 0) s.target = crowd_root_share(o, s.target_source);
    s.radius = radius_for_root_share(set.clips, roots, s.target, std::min(4000, o.tests), o.seed + 1);
    set.queries = random_tests(set.clips, s.radius, o.tests, o.seed);
    s.achieved = root_share(roots, set.queries);
    return set;
}

BenchTable run_table2(const Table2Options& o, const std::function<void(double)>& progress) {
    BenchTable t;
    t.workload = !o.workload.empty() ? o.workload : o.synth ? "synth" + fixed(o.synth_seconds, 0) : "table2";
    Table2Setup setup;
    const QuerySet set = table2_query_set(o, &setup);
    if (progress) progress(0.15);
    if (!o.save_queries.empty()) save_query_set(set, o.save_queries);
    t.rows = time_methods(set, make_methods(table_methods(), o.n_min), o.passes, progress_stage(progress, 0.15, 1.0),
                          o.slow_queries);
    add_targets(t, o);
    double total = 0;
    for (const Path& p : set.clips) total += p.duration();
    t.title = std::string("Table 2: ") + (o.synth ? "motion-graph sequences" : "longest clips") + " (" +
              std::to_string(set.clips.size()) + " motions, mean " + fixed(total / double(set.clips.size()), 1) +
              " s, " + std::to_string(o.tests) + " identical random tests)";
    add_notes(t, o, set, setup);
    if (progress) progress(1.0);
    return t;
}

QuerySet named_query_set(const std::string& name, const std::string& graph) {
    if (name == "seq42-30" || name == "seq42-60") return sequence42_set(name == "seq42-30" ? 30 : 60);
    if (name == "table1") {
        const crowd::MotionGraph g = crowd::load_graph(graph);
        crowd::CrowdOptions co;
        co.select = crowd::Selection::Random;
        co.log_queries = true;
        return crowd_query_set(g, crowd::run_crowd(g, crowd::NarrowPhase::sweep(g), co).queries);
    }
    Table2Options o;
    o.graph = graph;
    if (name == "synth42" || name == "synth120") {
        o.synth = true;
        o.synth_seconds = name == "synth42" ? 42 : 120;
        o.tests = name == "synth42" ? 20000 : 10000;
    } else if (name != "table2") {
        throw std::invalid_argument("unknown workload '" + name +
                                    "' (table1, table2, synth42, synth120, seq42-30, seq42-60)");
    }
    return table2_query_set(o);
}

}  // namespace mobb::bench
