// mobb graph build / crowd / bench table1 / bench table2: the crowd layer's subcommands (src/crowd).
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli.h"
#include "mobb/crowd/bench_tables.h"
#include "mobb/crowd/crowd.h"
#include "mobb/crowd/motion_graph.h"

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
        ->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--hubs", o->hubs, "Hub poses whose matches become transition points")->check(CLI::Range(1, 100))
        ->capture_default_str();
    cmd->add_option("--fps", o->fps, "Resample every input to this rate")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--window", o->window, "Frames in a pose-distance window")->check(CLI::Range(1, 61))->capture_default_str();
    cmd->add_option("--min-clip", o->min_clip, "Shortest clip (s)")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--max-clip", o->max_clip, "Longest clip (s)")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--target-clip", o->target_clip, "Preferred clip length (s)")->check(CLI::PositiveNumber)->capture_default_str();
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

// "WxH" in metres.
void parse_world(const std::string& text, double& w, double& h) {
    const auto x = text.find('x');
    try {
        std::size_t u1 = 0, u2 = 0;
        if (x == std::string::npos) throw std::invalid_argument("");
        w = std::stod(text.substr(0, x), &u1);
        h = std::stod(text.substr(x + 1), &u2);
        if (u1 != x || u2 != text.size() - x - 1 || !(w > 0) || !(h > 0) || !std::isfinite(w) || !std::isfinite(h))
            throw std::invalid_argument("");
    } catch (const std::exception&) {
        throw InputError("--world: expected WxH in metres (e.g. 30x40), got '" + text + "'");
    }
}

// A progress bar on stderr, redrawn when the percentage changes.
std::function<void(double)> progress_bar(const std::string& label) {
    auto last = std::make_shared<int>(-1);
    return [label, last](double f) {
        const int pct = int(f * 100.0);
        if (pct == *last) return;
        *last = pct;
        const int w = 30, filled = pct * w / 100;
        std::cerr << "\r" << label << " [" << std::string(std::size_t(filled), '#') << std::string(std::size_t(w - filled), ' ')
                  << "] " << pct << " %" << (pct >= 100 ? "\n" : "") << std::flush;
    };
}

void add_crowd(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("crowd", "Simulate a graph-driven crowd with collision-free clip choice (paper section 5)");
    auto graph = std::make_shared<std::string>();
    auto world = std::make_shared<std::string>("30x40");
    auto select = std::make_shared<std::string>("avoid");
    auto record = std::make_shared<std::string>();
    auto o = std::make_shared<crowd::CrowdOptions>();
    auto tree = std::make_shared<TreeArgs>();
    auto quiet = std::make_shared<bool>(false);
    cmd->add_option("--graph", *graph, "Motion graph JSON (default: assets/graphs/cmu_locomotion.json)");
    cmd->add_option("--agents", o->agents, "Number of agents")->check(CLI::Range(1, 1000000))->capture_default_str();
    cmd->add_option("--world", *world, "World rectangle WxH (metres)")->capture_default_str();
    cmd->add_option("--seconds", o->seconds, "Simulated seconds")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    cmd->add_option("--select", *select, "Clip choice: avoid or random")->check(CLI::IsMember({"avoid", "random"}))
        ->capture_default_str();
    cmd->add_option("--cell", o->cell, "Broad-phase grid cell (metres)")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--record", *record, "Write the record (JSON) to this file");
    cmd->add_flag("--quiet", *quiet, "No progress bar");
    tree->add_to(*cmd, false);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            crowd::CrowdOptions opt = *o;
            parse_world(*world, opt.width, opt.height);
            opt.select = crowd::parse_selection(*select);
            const std::string file = graph->empty() ? crowd::default_graph_file() : *graph;
            const crowd::MotionGraph g = crowd::load_graph(file);
            const std::vector<Tree> trees = crowd::build_trees(g, tree->options());
            crowd::CrowdRun run = crowd::run_crowd(g, trees, opt, *quiet ? std::function<void(double)>() : progress_bar("crowd"));
            run.record.graph = file;
            run.record.tree = tree->type;
            if (!record->empty()) {
                std::ofstream f(*record);
                f << crowd::record_to_text(run.record, crowd::summary_json(run.summary));
                if (!f) throw InputError(*record + ": cannot write");
            }
            out << opt.agents << " agents, " << opt.width << " x " << opt.height << " m, " << opt.seconds << " s, seed "
                << opt.seed << ", " << *select << ", tree " << tree->type << ", graph " << file << " (" << g.clips.size()
                << " clips)\n"
                << crowd::summary_text(run.summary);
        });
    });
}

// Where a benchmark table goes: Markdown on stdout, and optionally JSON and PNG files.
struct TableOutputs {
    std::string json, png;
    bool quiet = false;

    void add_to(CLI::App& cmd) {
        cmd.add_option("--json", json, "Also write the table as JSON");
        cmd.add_option("--png", png, "Also write a bar chart of time per query (PNG)");
        cmd.add_flag("--quiet", quiet, "No progress bar");
    }
    void write(const crowd::BenchTable& t, std::ostream& out) const {
        if (!json.empty()) {
            std::ofstream f(json);
            f << crowd::table_json(t);
            if (!f) throw InputError(json + ": cannot write");
        }
        if (!png.empty()) crowd::write_table_png(t, png);
        out << crowd::table_markdown(t);
    }
    std::function<void(double)> progress(const std::string& label) const {
        return quiet ? std::function<void(double)>() : progress_bar(label);
    }
};

void add_table1(CLI::App& bench, int& exit_code) {
    auto* cmd = bench.add_subcommand("table1", "Paper Table 1: the crowd's queries replayed by every tree type, plus frame stepping");
    auto o = std::make_shared<crowd::Table1Options>();
    auto world = std::make_shared<std::string>("30x40");
    auto outputs = std::make_shared<TableOutputs>();
    auto quick = std::make_shared<bool>(false);
    cmd->add_option("--graph", o->graph, "Motion graph JSON (default: assets/graphs/cmu_locomotion.json)");
    cmd->add_option("--agents", o->agents, "Agents")->check(CLI::Range(1, 1000000))->capture_default_str();
    cmd->add_option("--world", *world, "World WxH (metres)")->capture_default_str();
    cmd->add_option("--seconds", o->seconds, "Simulated seconds")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    cmd->add_option("--passes", o->passes, "Timed passes per method (median)")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd->add_option("--nmin", o->n_min, "Samples per leaf")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    cmd->add_flag("--quick", *quick, "Smoke run: 20 agents, 10 s, 1 pass");
    outputs->add_to(*cmd);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            crowd::Table1Options opt = *o;
            parse_world(*world, opt.width, opt.height);
            if (opt.graph.empty()) opt.graph = crowd::default_graph_file();
            if (*quick) {
                opt.agents = std::min(opt.agents, 20);
                opt.seconds = std::min(opt.seconds, 10.0);
                opt.passes = 1;
            }
            outputs->write(crowd::run_table1(opt, {}, outputs->progress("table1")), out);
        });
    });
}

void add_table2(CLI::App& bench, int& exit_code) {
    auto* cmd = bench.add_subcommand("table2", "Paper Table 2: identical random tests on long motions, every tree type");
    auto o = std::make_shared<crowd::Table2Options>();
    auto outputs = std::make_shared<TableOutputs>();
    auto quick = std::make_shared<bool>(false);
    cmd->add_option("--graph", o->graph, "Motion graph JSON (for --synth and the crowd's root-overlap share)");
    cmd->add_flag("--synth", o->synth, "Motion-graph sequences instead of the longest clips of the data");
    cmd->add_option("--motions", o->motions, "Number of motions")->check(CLI::Range(1, 10000))->capture_default_str();
    cmd->add_option("--synth-seconds", o->synth_seconds, "Length of each --synth sequence (s)")->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--tests", o->tests, "Random tests (the same for every method)")->check(CLI::Range(1, 100000000))
        ->capture_default_str();
    cmd->add_option("--fps", o->fps, "Resample the clips to this rate")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--root-share", o->root_share, "Target share of root overlaps (default: measured on a crowd run)");
    cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    cmd->add_option("--passes", o->passes, "Timed passes per method (median)")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd->add_option("--nmin", o->n_min, "Samples per leaf")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    cmd->add_flag("--quick", *quick, "Smoke run: 2,000 tests, a 20-agent 10 s crowd for the target share, 1 pass");
    outputs->add_to(*cmd);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            crowd::Table2Options opt = *o;
            if (opt.graph.empty()) opt.graph = crowd::default_graph_file();
            if (opt.root_share > 1) throw InputError("--root-share: must be at most 1");
            if (*quick) {
                opt.tests = std::min(opt.tests, 2000);
                opt.crowd_agents = 20;
                opt.crowd_seconds = 10;
                opt.passes = 1;
            }
            outputs->write(crowd::run_table2(opt, {}, outputs->progress("table2")), out);
        });
    });
}

void add_bench(CLI::App& app, int& exit_code) {
    auto* bench = app.add_subcommand("bench", "The paper's experiments (section 5), every row measured in one run");
    bench->require_subcommand(1);
    add_table1(*bench, exit_code);
    add_table2(*bench, exit_code);
}

}  // namespace

void add_crowd_commands(CLI::App& app, int& exit_code) {
    add_graph(app, exit_code);
    add_crowd(app, exit_code);
    add_bench(app, exit_code);
}

}  // namespace mobb::app
