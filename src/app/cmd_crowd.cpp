// mobb graph build / crowd: the crowd layer's subcommands (src/crowd).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
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

void add_crowd(CLI::App& app, int& exit_code) {
    auto* cmd =
        app.add_subcommand("crowd", "Simulate a graph-driven crowd with collision-free clip choice (paper section 5)");
    auto graph = std::make_shared<std::string>();
    auto world = std::make_shared<std::string>("30x40");
    auto select = std::make_shared<std::string>("avoid");
    auto record = std::make_shared<std::string>();
    auto scenario = std::make_shared<std::string>();
    auto o = std::make_shared<crowd::CrowdOptions>();
    o->threads = util::WorkerPool::hardware_threads();
    auto tree = std::make_shared<TreeArgs>();
    auto quiet = std::make_shared<bool>(false);
    auto no_motion = std::make_shared<bool>(false);
    cmd->add_option("--graph", *graph, "Motion graph JSON (default: assets/graphs/cmu_locomotion.json)");
    cmd->add_option("--agents", o->agents, "Number of agents")->check(CLI::Range(1, 1000000))->capture_default_str();
    cmd->add_option("--world", *world, "World rectangle WxH (metres)")->capture_default_str();
    cmd->add_option("--seconds", o->seconds, "Simulated seconds")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    cmd->add_option("--select", *select, "Clip choice: avoid (wander), random (the paper's timing) or goal")
        ->check(CLI::IsMember({"avoid", "random", "goal"}))
        ->capture_default_str();
    cmd->add_option("--cell", o->cell, "Broad-phase grid cell (metres)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--threads", o->threads,
                    "Worker threads for the choice points (the record is the same for any count)")
        ->check(CLI::Range(1, 1024))
        ->capture_default_str();
    cmd->add_option("--record", *record, "Write the record to this file: JSON, or HDF5 for .h5 (docs/formats.md)");
    auto candidates = std::make_shared<bool>(false);
    cmd->add_flag("--record-candidates,!--no-record-candidates", *candidates,
                  "Keep each choice point's candidates and their queries in the record (default: in a JSON record, "
                  "not in HDF5, where they would be most of the file's tables and slow the run)");
    cmd->add_option("--scenario", *scenario,
                    "Run a scenario (JSON: world, obstacles, agents with goals, time limit; assets/scenarios)");
    // Each rule can be switched off (include/mobb/crowd/tuning.h), so its effect is one command away.
    auto off = std::make_shared<crowd::CrowdTuning>();
    const auto rule_off = [&](const char* flag, bool crowd::CrowdTuning::*rule, const char* what) {
        cmd->add_flag_callback(
            flag, [off, rule] { (*off).*rule = false; }, what);
    };
    rule_off("--no-look-ahead", &crowd::CrowdTuning::look_ahead,
             "Goal agents try their candidates in the policy's order alone, without searching clip sequences");
    rule_off("--no-follow", &crowd::CrowdTuning::follow,
             "Goal agents' look-ahead treats the reservations of agents going their way as walls, beyond the "
             "first clip too");
    rule_off("--no-right-of-way", &crowd::CrowdTuning::right_of_way,
             "An agent that waited never pushes others' reservations aside");
    rule_off("--no-give-way", &crowd::CrowdTuning::give_way, "Walkers do not keep clear of agents that wait");
    rule_off("--no-stand-near-walls", &crowd::CrowdTuning::stand_near_walls,
             "Held ground keeps room to turn on the spot from walls and obstacles, not only room to stand");
    rule_off("--no-leave-in-stride", &crowd::CrowdTuning::leave_in_stride,
             "Agents leaving at an exit reserve a stop beyond it, as any clip's plan does");
    rule_off("--no-standing-gap", &crowd::CrowdTuning::standing_gap,
             "Wanderers may stop right beside another's held ground");
    auto tune = std::make_shared<std::vector<std::string>>();
    cmd->add_option("--tune", *tune,
                    "Set a field of CrowdTuning, NAME=VALUE (repeatable; include/mobb/crowd/tuning.h), e.g. "
                    "--tune look_ahead_budget=192");
    cmd->add_flag("--quiet", *quiet, "No progress bar");
    cmd->add_flag("--no-motion", *no_motion,
                  "Skip the motion metrics (joint jumps, foot sliding: they pose every agent from the mocap)");
    tree->add_to(*cmd, false);
    cmd->callback([=, &exit_code] {
        // A scenario brings its own world, agents, policy and time limit.
        for (const char* own : {"--agents", "--world", "--select", "--seconds"})
            if (!scenario->empty() && cmd->count(own)) {
                std::cerr << "crowd: " << own << " does not go with --scenario (the scenario sets it)\n";
                exit_code = kUsage;
                return;
            }
        if (record->empty() && cmd->count("--record-candidates")) {
            std::cerr << "crowd: --record-candidates and --no-record-candidates go with --record\n";
            exit_code = kUsage;
            return;
        }
        for (const std::string& t : *tune) {
            try {
                crowd::set_tuning(*off, t);
            } catch (const std::invalid_argument& e) {
                std::cerr << "crowd: --tune " << e.what() << "\n";
                exit_code = kUsage;
                return;
            }
        }
        exit_code = guarded([&](std::ostream& out) {
            crowd::CrowdOptions opt = *o;
            parse_world(*world, opt.world.x1, opt.world.y1);
            opt.select = crowd::parse_selection(*select);
            crowd::Scenario s;
            if (!scenario->empty()) {
                s = crowd::load_scenario(*scenario);
                opt = crowd::scenario_options(s);
                opt.seed = o->seed;
                opt.threads = o->threads;
                opt.cell = o->cell;
            }
            opt.tuning = *off;
            // Only a written record shows them, and an HDF5 one only when asked.
            opt.record_queries = !record->empty() &&
                                 (cmd->count("--record-candidates") ? *candidates : crowd::keeps_candidates(*record));
            const std::string file = graph->empty() ? crowd::default_graph_file() : *graph;
            const crowd::MotionGraph g = crowd::load_graph(file);
            // The fastest exact query unless a tree is asked for (its counters then fill the summary).
            const bool trees = cmd->count("--tree") || cmd->count("--nmin") || cmd->count("--fit");
            const crowd::NarrowPhase narrow =
                trees ? crowd::NarrowPhase::trees(g, tree->options()) : crowd::NarrowPhase::sweep(g);
            // An HDF5 record streams as the run goes; a JSON one (small runs) is written at the end. Without a
            // record the run streams to nowhere, keeping only its summary and metrics (memory stays flat) -
            // unless its motion is measured, which poses the clips the run keeps (kMotionAgents at most).
            const bool at_end = !record->empty() && !crowd::is_h5_record(*record);
            const bool motion = !*no_motion && (at_end || (record->empty() && opt.agents <= kMotionAgents));
            crowd::RecordSink nowhere;
            std::unique_ptr<crowd::H5RecordWriter> writer;
            if (!record->empty() && !at_end) writer = std::make_unique<crowd::H5RecordWriter>(*record, file, s.name);
            if (!at_end && !motion) opt.sink = writer ? writer.get() : &nowhere;
            crowd::CrowdRun run;
            try {
                run = crowd::run_crowd(g, narrow, opt, *quiet ? std::function<void(double)>() : progress_bar("crowd"));
            } catch (const std::invalid_argument& e) {
                if (writer) writer.reset(), std::remove(record->c_str());  // bad options: no frame, no file
                if (scenario->empty()) throw;
                throw InputError(*scenario + ": " + e.what());  // its agents cannot start where it puts them
            }
            run.record.graph = file;
            run.record.scenario = s.name;
            const crowd::CrowdMetrics metrics =
                run.metrics ? *run.metrics : crowd::crowd_metrics(run.record, g, opt.goal_radius);
            std::string metrics_json = crowd::metrics_json(metrics), motion_text;
            if (motion)
                measure_motion(run.record, g, opt.threads, metrics_json, motion_text);
            else if (!*no_motion)
                motion_text = "motion: not measured (a streamed run keeps no clips to pose: a JSON record, or " +
                              std::to_string(kMotionAgents) + " agents or fewer)\n";
            if (writer)
                writer->finish(run.record, crowd::summary_json(run.summary), metrics_json);
            else if (at_end)
                crowd::write_record_file(*record, run.record, crowd::summary_json(run.summary), metrics_json);
            if (!s.name.empty()) out << "scenario " << s.name << ": ";
            out << opt.agents << " agents, " << opt.world.width() << " x " << opt.world.height() << " m, "
                << opt.seconds << " s, seed " << opt.seed << ", " << crowd::to_string(opt.select) << ", narrow phase "
                << narrow.name() << ", " << opt.threads << " threads, graph " << file << " (" << g.clips.size()
                << " clips)\n"
                << crowd::summary_text(run.summary) << crowd::metrics_text(metrics) << motion_text;
        });
    });
}

}  // namespace

void add_crowd_commands(CLI::App& app, int& exit_code) {
    add_graph(app, exit_code);
    add_crowd(app, exit_code);
}

}  // namespace mobb::app
