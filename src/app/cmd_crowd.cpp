// mobb graph build / crowd: the crowd layer's subcommands (src/crowd).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "cli.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/motion/motion_metrics.h"
#include "mobb/crowd/record/record_file.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/sim/crowd.h"
#include "mobb/util/worker_pool.h"

namespace mobb::app {

namespace {

void add_graph(CLI::App& app, int& exit_code) {
    auto* graph = app.add_subcommand("graph", "Motion graphs built from mocap");
    graph->require_subcommand(1);
    auto* cmd = graph->add_subcommand("build", "Build a motion graph from BVH/glTF files (Kovar et al. 2002)");
    auto files = std::make_shared<std::vector<std::string>>();
    auto out_file = std::make_shared<std::string>();
    auto o = std::make_shared<crowd::GraphBuildOptions>();
    cmd->add_option("FILES", *files, "Input clips")->required();
    cmd->add_option("--out", *out_file, "Graph JSON to write")->required();
    cmd->add_option("--threshold", o->threshold, "Pose distance for transitions and edges (metres, RMS)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--hubs", o->hubs, "Hub poses whose matches become transition points")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    cmd->add_option("--fps", o->fps, "Resample every input to this rate")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--window", o->window, "Frames in a pose-distance window")
        ->check(CLI::Range(1, 61))
        ->capture_default_str();
    cmd->add_option("--min-clip", o->min_clip, "Shortest clip (s)")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--max-clip", o->max_clip, "Longest clip (s)")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--target-clip", o->target_clip, "Preferred clip length (s)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    const std::map<std::string, io::PathCentre> centres{{"root", io::PathCentre::Root},
                                                        {"enclosing", io::PathCentre::Enclosing}};
    cmd->add_option("--centre", o->centre,
                    "Centre of the clips' disks: root (the paper's) or enclosing (the smallest disk holding the body)")
        ->transform(CLI::CheckedTransformer(centres, CLI::ignore_case))
        ->default_str("root");
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            const auto start = std::chrono::steady_clock::now();
            crowd::MotionGraph g = crowd::build_motion_graph(*files, *o, &std::cerr);
            g.command = "mobb graph build";
            for (const std::string& f : *files) g.command += " " + f;
            std::ostringstream opts;
            opts << " --out " << *out_file << " --threshold " << o->threshold << " --fps " << o->fps << " --window "
                 << o->window << " --hubs " << o->hubs << " --min-clip " << o->min_clip << " --max-clip " << o->max_clip
                 << " --target-clip " << o->target_clip;
            if (o->centre == io::PathCentre::Enclosing) opts << " --centre enclosing";
            g.command += opts.str();
            crowd::save_graph(g, *out_file);
            const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            double total = 0;
            std::size_t edges = 0;
            for (const auto& c : g.clips) {
                total += c.path.duration();
                edges += c.successors.size();
            }
            out << *out_file << ": " << g.clips.size() << " clips (mean " << total / double(g.clips.size()) << " s), "
                << edges << " edges, " << g.transitions << " transition points, built in " << secs << " s\n";
        });
    });
}

// Runs without a record larger than this stream rather than keep their clips to pose for the motion
// metrics (1,000 agents x 120 s take some 17 s to pose on two threads: docs/export.md).
constexpr int kMotionAgents = 1000;

// The motion metrics of a run's record (joint jumps, foot sliding; motion_metrics.h) into the record's
// metrics JSON and the summary's text; without the motion capture, a line saying why not.
void measure_motion(const crowd::Record& record, const crowd::MotionGraph& g, int threads, std::string& metrics_json,
                    std::string& text) {
    try {
        const crowd::CrowdMotion m = crowd::crowd_motion(record, std::make_shared<const crowd::MotionGraph>(g),
                                                         crowd::PoseBlend{}.window, threads);
        metrics_json = crowd::with_motion(metrics_json, m);
        text = crowd::motion_text(m);
    } catch (const io::LoadError& e) {  // no motion capture here
        text = std::string("motion: not measured (") + e.what() + ")\n";
    } catch (const crowd::GraphError& e) {  // a source not as the graph was built from it
        text = std::string("motion: not measured (") + e.what() + ")\n";
    }
}

// What `mobb crowd` reads from its command line.
struct CrowdArgs {
    CLI::App* cmd = nullptr;
    std::string graph, world = "30x40", select = "wander", record, scenario;
    crowd::CrowdOptions options;
    crowd::CrowdTuning tuning;  // the rules' switches and numbers (--no-..., --tune)
    std::vector<std::string> tune;
    TreeArgs tree;
    bool quiet = false, no_motion = false, candidates = false;
};

void add_run_options(CLI::App& cmd, CrowdArgs& a) {
    crowd::CrowdOptions& o = a.options;
    cmd.add_option("--graph", a.graph, "Motion graph JSON (default: assets/graphs/cmu_locomotion.json)");
    cmd.add_option("--agents", o.agents, "Number of agents")->check(CLI::Range(1, 1000000))->capture_default_str();
    cmd.add_option("--world", a.world, "World rectangle WxH (metres)")->capture_default_str();
    cmd.add_option("--seconds", o.seconds, "Simulated seconds")->check(CLI::PositiveNumber)->capture_default_str();
    cmd.add_option("--seed", o.seed, "Random seed")->capture_default_str();
    cmd.add_option("--select", a.select,
                   "Clip choice: wander, random (the paper's timing) or goal (avoid: wander's old name)")
        ->check(CLI::IsMember({"wander", "random", "goal", "avoid"}))
        ->capture_default_str();
    cmd.add_option("--cell", o.cell, "Broad-phase grid cell (metres)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd.add_option("--threads", o.threads,
                   "Worker threads for the choice points (the record is the same for any count)")
        ->check(CLI::Range(1, 1024))
        ->capture_default_str();
    cmd.add_option("--max-batch", o.max_batch,
                   "Choice points evaluated at once, at most: a frame with more runs them in batches (the record's "
                   "agents do the same for any size; only the work, time and memory differ)")
        ->check(CLI::Range(1, 1 << 30))
        ->capture_default_str();
    cmd.add_option("--record", a.record, "Write the record to this file: JSON, or HDF5 for .h5 (docs/formats.md)");
    cmd.add_flag("--record-candidates,!--no-record-candidates", a.candidates,
                 "Keep each choice point's candidates and their queries in the record (default: in a JSON record, "
                 "not in HDF5, where they would be most of the file's tables and slow the run)");
    cmd.add_option("--scenario", a.scenario,
                   "Run a scenario (JSON: world, obstacles, agents with goals, time limit; assets/scenarios)");
    cmd.add_flag("--quiet", a.quiet, "No progress bar");
    cmd.add_flag("--no-motion", a.no_motion,
                 "Skip the motion metrics (joint jumps, foot sliding: they pose every agent from the mocap)");
    a.tree.add_to(cmd, false);
}

// Each rule can be switched off (include/mobb/crowd/tuning.h), so its effect is one command away.
void add_rule_switches(CLI::App& cmd, crowd::CrowdTuning& off, std::vector<std::string>& tune) {
    const auto rule_off = [&](const char* flag, bool& rule, const char* what) {
        cmd.add_flag_callback(
            flag, [&rule] { rule = false; }, what);
    };
    rule_off("--no-look-ahead", off.look_ahead.on,
             "Goal agents try their candidates in the policy's order alone, without searching clip sequences");
    rule_off("--no-follow", off.follow.on,
             "Goal agents' look-ahead treats the reservations of agents going their way as walls, beyond the "
             "first clip too");
    rule_off("--no-right-of-way", off.right_of_way.on, "An agent that waited never pushes others' reservations aside");
    rule_off("--no-give-way", off.give_way.on, "Walkers do not keep clear of agents that wait");
    rule_off("--no-let-through", off.let_through.on,
             "Goal agents at a passage do not keep out of the way of those coming through it the other way");
    rule_off("--no-keep-right", off.keep_right.on,
             "Goal agents in corridors and doors do not keep right of those coming the other way");
    rule_off("--no-face-along-walls", off.face_along_walls.on,
             "Goal agents rank ends beside a wall facing into it as any other");
    rule_off("--no-stand-near-walls", off.stand_near_walls.on,
             "Held ground keeps room to turn on the spot from walls and obstacles, not only room to stand");
    rule_off("--no-leave-in-stride", off.leave_in_stride.on,
             "Agents leaving at an exit reserve a stop beyond it, as any clip's plan does");
    rule_off("--no-standing-gap", off.standing_gap.on, "Wanderers may stop right beside another's held ground");
    cmd.add_option("--tune", tune,
                   "Set a field of CrowdTuning, NAME=VALUE (repeatable; include/mobb/crowd/tuning.h), e.g. "
                   "--tune look_ahead.budget=192 (the flat names of before, look_ahead_budget=192, still work)");
}

// The usage errors the parser cannot see: options that do not go together, a bad --tune. Prints one line
// and returns false on the first.
bool check_usage(CrowdArgs& a) {
    // A scenario brings its own world, agents, policy and time limit.
    for (const char* own : {"--agents", "--world", "--select", "--seconds"})
        if (!a.scenario.empty() && a.cmd->count(own)) {
            std::cerr << "crowd: " << own << " does not go with --scenario (the scenario sets it)\n";
            return false;
        }
    if (a.record.empty() && a.cmd->count("--record-candidates")) {
        std::cerr << "crowd: --record-candidates and --no-record-candidates go with --record\n";
        return false;
    }
    for (const std::string& t : a.tune) {
        try {
            crowd::set_tuning(a.tuning, t);
        } catch (const std::invalid_argument& e) {
            std::cerr << "crowd: --tune " << e.what() << "\n";
            return false;
        }
    }
    return true;
}

// The run's options: the command line's, or a scenario's with the command line's seed, threads, batch and
// cell.
crowd::CrowdOptions run_options(const CrowdArgs& a, const crowd::Scenario& s) {
    crowd::CrowdOptions opt = a.options;
    parse_world(a.world, opt.world.x1, opt.world.y1);
    opt.select = crowd::parse_selection(a.select);
    if (!a.scenario.empty()) {
        opt = crowd::scenario_options(s);
        opt.seed = a.options.seed;
        opt.threads = a.options.threads;
        opt.max_batch = a.options.max_batch;
        opt.cell = a.options.cell;
    }
    opt.tuning = a.tuning;
    // Only a written record shows them, and an HDF5 one only when asked.
    opt.record_queries =
        !a.record.empty() && (a.cmd->count("--record-candidates") ? a.candidates : crowd::keeps_candidates(a.record));
    return opt;
}

// A JSON record is held whole and written at the end of the run (record_file.h): one that would need more
// memory than the limit is refused before the run, from the choice points the simulation expects - one per
// agent per clip, the graph's clips of their mean length - and no file is written.
void check_json_record(const std::string& record, const crowd::CrowdOptions& opt, const crowd::MotionGraph& g) {
    std::size_t samples = 0;
    for (const crowd::GraphClip& c : g.clips) samples += c.path.size();
    const double clip_frames = std::max(1.0, double(samples) / double(std::max<std::size_t>(1, g.clips.size())));
    const std::int64_t frames = std::max<std::int64_t>(1, std::llround(opt.seconds / g.dt()));
    const auto agents = std::uint64_t(opt.agents);
    const auto choices = std::uint64_t(double(agents) * (double(frames) / clip_frames + 1));
    crowd::check_json_record_write(
        record, crowd::expected_json_record(agents, frames, choices, crowd::to_string(opt.select), opt.record_queries));
}

void run_crowd_command(const CrowdArgs& a, std::ostream& out) {
    crowd::Scenario s;
    if (!a.scenario.empty()) s = crowd::load_scenario(a.scenario);
    crowd::CrowdOptions opt = run_options(a, s);
    const std::string file = a.graph.empty() ? crowd::default_graph_file() : a.graph;
    const crowd::MotionGraph g = crowd::load_graph(file);
    const bool at_end = !a.record.empty() && !crowd::is_h5_record(a.record);
    if (at_end) check_json_record(a.record, opt, g);
    // The fastest exact query unless a tree is asked for (its counters then fill the summary).
    const bool trees = a.cmd->count("--tree") || a.cmd->count("--nmin") || a.cmd->count("--fit");
    const crowd::NarrowPhase narrow =
        trees ? crowd::NarrowPhase::trees(g, a.tree.options()) : crowd::NarrowPhase::sweep(g);
    // An HDF5 record streams as the run goes; a JSON one (small runs) is written at the end. Without a
    // record the run streams to nowhere, keeping only its summary and metrics (memory stays flat) -
    // unless its motion is measured, which poses the clips the run keeps (kMotionAgents at most).
    const bool motion = !a.no_motion && (at_end || (a.record.empty() && opt.agents <= kMotionAgents));
    crowd::RecordSink nowhere;
    std::unique_ptr<crowd::H5RecordWriter> writer;
    if (!a.record.empty() && !at_end) writer = std::make_unique<crowd::H5RecordWriter>(a.record, file, s.name);
    if (!at_end && !motion) opt.sink = writer ? writer.get() : &nowhere;
    crowd::CrowdRun run;
    try {
        run = crowd::run_crowd(g, narrow, opt, a.quiet ? std::function<void(double)>() : progress_bar("crowd"));
    } catch (const std::invalid_argument& e) {
        if (writer) writer.reset(), std::remove(a.record.c_str());  // bad options: no frame, no file
        if (a.scenario.empty()) throw;
        throw InputError(a.scenario + ": " + e.what());  // its agents cannot start where it puts them
    }
    run.record.graph = file;
    run.record.scenario = s.name;
    const crowd::CrowdMetrics metrics =
        run.metrics ? *run.metrics : crowd::crowd_metrics(run.record, g, opt.goal_radius);
    std::string metrics_json = crowd::metrics_json(metrics), motion_text;
    if (motion)
        measure_motion(run.record, g, opt.threads, metrics_json, motion_text);
    else if (!a.no_motion)
        motion_text = "motion: not measured (a streamed run keeps no clips to pose: a JSON record, or " +
                      std::to_string(kMotionAgents) + " agents or fewer)\n";
    if (writer)
        writer->finish(run.record, crowd::summary_json(run.summary), metrics_json);
    else if (at_end)
        crowd::write_record_file(a.record, run.record, crowd::summary_json(run.summary), metrics_json);
    if (!s.name.empty()) out << "scenario " << s.name << ": ";
    out << opt.agents << " agents, " << opt.world.width() << " x " << opt.world.height() << " m, " << opt.seconds
        << " s, seed " << opt.seed << ", " << crowd::to_string(opt.select) << ", narrow phase " << narrow.name() << ", "
        << opt.threads << " threads, graph " << file << " (" << g.clips.size() << " clips)\n"
        << crowd::summary_text(run.summary) << crowd::metrics_text(metrics) << motion_text;
}

void add_crowd(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<CrowdArgs>();
    a->cmd =
        app.add_subcommand("crowd", "Simulate a graph-driven crowd with collision-free clip choice (paper section 5)");
    a->options.threads = util::WorkerPool::hardware_threads();
    add_run_options(*a->cmd, *a);
    add_rule_switches(*a->cmd, a->tuning, a->tune);
    a->cmd->callback([a, &exit_code] {
        if (!check_usage(*a)) {
            exit_code = kUsage;
            return;
        }
        exit_code = guarded([&](std::ostream& out) { run_crowd_command(*a, out); });
    });
}

}  // namespace

void add_crowd_commands(CLI::App& app, int& exit_code) {
    add_graph(app, exit_code);
    add_crowd(app, exit_code);
}

}  // namespace mobb::app
