// mobb bench ...: the paper's experiments and the performance workloads (src/bench).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>

#include "cli.h"
#include "crowd_quality.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/scenario/scenario.h"
#include "report.h"
#include "steersuite_cases.h"

namespace mobb::app {

namespace {

// Where a benchmark table goes: Markdown on stdout, and optionally JSON and PNG files.
struct TableOutputs {
    std::string json, png;
    bool quiet = false;

    void add_to(CLI::App& cmd, const std::string& chart = "time per query") {
        cmd.add_option("--json", json, "Also write the table as JSON");
        cmd.add_option("--png", png, "Also write a bar chart of " + chart + " (PNG)");
        cmd.add_flag("--quiet", quiet, "No progress bar");
    }
    /// The JSON file, the chart (write_png(file) when asked for) and the Markdown on `out`.
    void emit(const std::string& json_text, const std::function<void(const std::string&)>& write_png,
              const std::string& markdown, std::ostream& out) const {
        if (!json.empty()) {
            std::ofstream f(json);
            f << json_text;
            if (!f) throw InputError(json + ": cannot write");
        }
        if (!png.empty()) write_png(png);
        out << markdown;
    }
    void write(const bench::BenchTable& t, std::ostream& out) const {
        emit(
            bench::table_json(t), [&](const std::string& file) { bench::write_table_png(t, file); },
            bench::table_markdown(t), out);
    }
    std::function<void(double)> progress(const std::string& label) const {
        return quiet ? std::function<void(double)>() : progress_bar(label);
    }
};

void add_table1(CLI::App& bench, int& exit_code) {
    auto* cmd = bench.add_subcommand(
        "table1", "Paper Table 1: the crowd's queries replayed by every method, plus frame stepping");
    auto o = std::make_shared<bench::Table1Options>();
    auto world = std::make_shared<std::string>("30x40");
    auto outputs = std::make_shared<TableOutputs>();
    auto quick = std::make_shared<bool>(false);
    cmd->add_option("--graph", o->graph, "Motion graph JSON (default: assets/graphs/cmu_locomotion.json)");
    cmd->add_option("--agents", o->agents, "Agents")->check(CLI::Range(1, 1000000))->capture_default_str();
    cmd->add_option("--world", *world, "World WxH (metres)")->capture_default_str();
    cmd->add_option("--seconds", o->seconds, "Simulated seconds")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    cmd->add_option("--passes", o->passes, "Timed passes per method (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_option("--nmin", o->n_min, "Samples per leaf")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    cmd->add_option("--slow-queries", o->slow_queries, "Brute force and FCL are timed on this many queries")
        ->check(CLI::Range(1, 100000000))
        ->capture_default_str();
    cmd->add_option("--save-queries", o->save_queries,
                    "Write the replayed queries there (for bench/callgrind_workload.sh)");
    cmd->add_flag("--quick", *quick, "Smoke run: 20 agents, 10 s, 1 pass");
    outputs->add_to(*cmd);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            bench::Table1Options opt = *o;
            parse_world(*world, opt.width, opt.height);
            if (opt.graph.empty()) opt.graph = crowd::default_graph_file();
            if (*quick) {
                opt.agents = std::min(opt.agents, 20);
                opt.seconds = std::min(opt.seconds, 10.0);
                opt.passes = 1;
            }
            outputs->write(bench::run_table1(opt, outputs->progress("table1")), out);
        });
    });
}

// Options shared by table2, synth42 and synth120.
void add_random_test_options(CLI::App& cmd, bench::Table2Options& o) {
    cmd.add_option("--graph", o.graph,
                   "Motion graph JSON (for motion-graph sequences and the crowd's root-overlap share)");
    cmd.add_option("--motions", o.motions, "Number of motions")->check(CLI::Range(1, 10000))->capture_default_str();
    cmd.add_option("--tests", o.tests, "Random tests (the same for every method)")
        ->check(CLI::Range(1, 100000000))
        ->capture_default_str();
    cmd.add_option("--fps", o.fps, "Resample the clips to this rate")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd.add_option("--root-share", o.root_share, "Target share of root overlaps (default: measured on a crowd run)");
    cmd.add_option("--seed", o.seed, "Random seed")->capture_default_str();
    cmd.add_option("--passes", o.passes, "Timed passes per method (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd.add_option("--nmin", o.n_min, "Samples per leaf")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    cmd.add_option("--slow-queries", o.slow_queries, "Brute force and FCL are timed on this many tests")
        ->check(CLI::Range(1, 100000000))
        ->capture_default_str();
    cmd.add_option("--save-queries", o.save_queries, "Write the tests there (for bench/callgrind_workload.sh)");
}

// The run of table2 / synth42 / synth120 with the parsed options.
void run_random_tests(bench::Table2Options opt, bool quick, const TableOutputs& outputs, const std::string& label,
                      std::ostream& out) {
    if (opt.graph.empty()) opt.graph = crowd::default_graph_file();
    if (opt.root_share > 1) throw InputError("--root-share: must be at most 1");
    if (quick) {
        opt.tests = std::min(opt.tests, 2000);
        opt.crowd_agents = 20;
        opt.crowd_seconds = 10;
        opt.passes = 1;
        opt.slow_queries = std::min<std::size_t>(opt.slow_queries, 200);
    }
    outputs.write(bench::run_table2(opt, outputs.progress(label)), out);
}

void add_table2(CLI::App& bench, int& exit_code) {
    auto* cmd = bench.add_subcommand("table2", "Paper Table 2: identical random tests on long motions, every method");
    auto o = std::make_shared<bench::Table2Options>();
    auto outputs = std::make_shared<TableOutputs>();
    auto quick = std::make_shared<bool>(false);
    add_random_test_options(*cmd, *o);
    cmd->add_flag("--synth", o->synth, "Motion-graph sequences instead of the longest clips of the data");
    cmd->add_option("--synth-seconds", o->synth_seconds, "Length of each --synth sequence (s)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_flag("--quick", *quick, "Smoke run: 2,000 tests, a 20-agent 10 s crowd for the target share, 1 pass");
    outputs->add_to(*cmd);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) { run_random_tests(*o, *quick, *outputs, "table2", out); });
    });
}

// synth42 / synth120: Table 2's protocol on motion-graph sequences of `seconds` each.
void add_synth(CLI::App& bench, int& exit_code, int seconds, int tests) {
    const std::string name = "synth" + std::to_string(seconds);
    auto* cmd = bench.add_subcommand(
        name, "Table 2's random tests on " + std::to_string(seconds) + " s motion-graph sequences, every method");
    auto o = std::make_shared<bench::Table2Options>();
    o->synth = true;
    o->synth_seconds = seconds;
    o->tests = tests;
    o->workload = name;
    auto outputs = std::make_shared<TableOutputs>();
    auto quick = std::make_shared<bool>(false);
    add_random_test_options(*cmd, *o);
    cmd->add_flag("--quick", *quick, "Smoke run: 2,000 tests, a 20-agent 10 s crowd for the target share, 1 pass");
    outputs->add_to(*cmd);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) { run_random_tests(*o, *quick, *outputs, name, out); });
    });
}

void add_scale(CLI::App& bench, int& exit_code) {
    auto* cmd = bench.add_subcommand(
        "scale", "The avoiding crowd at the paper's density for growing agent counts and thread counts");
    auto o = std::make_shared<bench::ScaleOptions>();
    auto outputs = std::make_shared<TableOutputs>();
    auto quick = std::make_shared<bool>(false);
    cmd->add_option("--graph", o->graph, "Motion graph JSON (default: assets/graphs/cmu_locomotion.json)");
    cmd->add_option("--agents", o->agents, "Crowd sizes (the first is the reference)")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--seconds", o->seconds, "Simulated seconds")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--area", o->area_per_agent, "Square metres per agent")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--threads", o->threads,
                    "Thread counts of every size's runs, the first the speed-ups' reference (e.g. 1,2,4,8,16; "
                    "0: all hardware threads; one count N other than 1 means 1,N)")
        ->delimiter(',')
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cmd->add_option("--repeats", o->repeats, "Runs per size and thread count (medians)")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    cmd->add_option(
        "--save-queries", o->save_queries,
        "Write up to 5,000 queries of each size's crowd to FILE.<agents> (for bench/callgrind_workload.sh)");
    auto million = std::make_shared<bool>(false);
    cmd->add_flag("--million", *million,
                  "Add 1,000,000 agents, on the parallel threads only (measured: 8.2 GB, about 1,300 s of CPU: "
                  "13 minutes on 2 cores)");
    cmd->add_flag("--quick", *quick, "Smoke run: 10 and 40 agents, 5 s, 1 repeat");
    outputs->add_to(*cmd);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            bench::ScaleOptions opt = *o;
            if (*million) opt.agents.push_back(1000000);
            if (opt.graph.empty()) opt.graph = crowd::default_graph_file();
            for (int n : opt.agents)
                if (n < 1) throw InputError("--agents: every size must be at least 1");
            if (opt.threads.size() == 1 && opt.threads.front() != 1) opt.threads.insert(opt.threads.begin(), 1);
            if (*quick) {
                opt.agents = {10, 40};
                opt.seconds = std::min(opt.seconds, 5.0);
                opt.repeats = 1;
            }
            const bench::ScaleTable t = bench::run_scale(opt, outputs->progress("scale"));
            outputs->emit(
                bench::scale_json(t), [&](const std::string& file) { bench::write_scale_png(t, file); },
                bench::scale_markdown(t), out);
        });
    });
}

void add_crowd_quality(CLI::App& bench, int& exit_code) {
    auto* cmd = bench.add_subcommand("crowd",
                                     "The avoiding crowd: wander at the paper's density and every scenario, "
                                     "several seeds, with their metrics and the crowd's targets");
    auto o = std::make_shared<bench::CrowdQualityOptions>();
    auto outputs = std::make_shared<TableOutputs>();
    auto quick = std::make_shared<bool>(false);
    auto scenarios = std::make_shared<std::string>();
    cmd->add_option("--graph", o->graph, "Motion graph JSON (default: assets/graphs/cmu_locomotion.json)");
    cmd->add_option("--scenarios", *scenarios, "Folder of scenario files (default: assets/scenarios)");
    cmd->add_option("--seeds", o->seeds, "Seeds of every run")->delimiter(',')->capture_default_str();
    cmd->add_option("--threads", o->threads, "Threads per run (the CD cost is measured on 1)")
        ->check(CLI::Range(1, 1024))
        ->capture_default_str();
    cmd->add_option("--baseline-us", o->baseline_us,
                    "CD us per agent per simulated second before the escapes (10,000 agents, MOBB tree, 1 thread)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_flag("--quick", *quick, "Smoke run: 30 and 60 agents for 20 s, two scenarios, one seed");
    outputs->add_to(*cmd, "idle share (wander) and time to the last goal (scenarios)");
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            bench::CrowdQualityOptions opt = *o;
            if (opt.graph.empty()) opt.graph = crowd::default_graph_file();
            const std::string folder = scenarios->empty() ? crowd::default_scenario_folder() : *scenarios;
            opt.scenarios = crowd::scenario_files(folder);
            if (opt.scenarios.empty()) throw InputError(folder + ": no scenario files (*.json)");
            if (*quick) {
                opt.wander = {{30, 20, 20, 20}, {60, 24, 30, 20}};
                opt.scenarios.resize(std::min<std::size_t>(2, opt.scenarios.size()));
                opt.seeds = {opt.seeds.front()};
            }
            const bench::CrowdQualityTable t = bench::run_crowd_quality(opt, outputs->progress("crowd"));
            outputs->emit(
                bench::crowd_quality_json(t), [&](const std::string& file) { bench::write_crowd_quality_png(t, file); },
                bench::crowd_quality_markdown(t), out);
        });
    });
}

// The test-case files (*.xml) of `folder`, sorted; InputError when there are none.
std::vector<std::string> test_case_files(const std::string& folder) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec))
        if (e.path().extension() == ".xml") out.push_back(e.path().string());
    if (ec) throw InputError(folder + ": " + ec.message());
    if (out.empty()) throw InputError(folder + ": no test-case files (*.xml)");
    std::sort(out.begin(), out.end());
    return out;
}

void add_steersuite(CLI::App& bench, int& exit_code) {
    auto* cmd = bench.add_subcommand("steersuite",
                                     "SteerSuite's test cases (a folder of XML), each imported and run with several "
                                     "seeds, judged per agent and scored with SteerSuite's composites");
    auto o = std::make_shared<bench::SteerSuiteOptions>();
    auto outputs = std::make_shared<TableOutputs>();
    auto folder = std::make_shared<std::string>();
    cmd->add_option("DIR", *folder, "Folder of test cases (e.g. ../shared/steersuite/testcases)")->required();
    cmd->add_option("--graph", o->graph, "Motion graph JSON (default: assets/graphs/cmu_locomotion.json)");
    cmd->add_option("--seeds", o->seeds, "Seeds of every case")->delimiter(',')->capture_default_str();
    cmd->add_option("--threads", o->threads, "Threads per run")->check(CLI::Range(1, 1024))->capture_default_str();
    outputs->add_to(*cmd, "time to goal over the straight line, every run");
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            bench::SteerSuiteOptions opt = *o;
            if (opt.graph.empty()) opt.graph = crowd::default_graph_file();
            opt.cases = test_case_files(*folder);
            const bench::SteerSuiteTable t = bench::run_steersuite(opt, outputs->progress("steersuite"));
            outputs->emit(
                bench::steersuite_json(t), [&](const std::string& file) { bench::write_steersuite_png(t, file); },
                bench::steersuite_markdown(t), out);
        });
    });
}

void add_bench(CLI::App& app, int& exit_code) {
    auto* bench = app.add_subcommand("bench", "The paper's experiments (section 5), every row measured in one run");
    bench->require_subcommand(1);
    add_table1(*bench, exit_code);
    add_table2(*bench, exit_code);
    add_synth(*bench, exit_code, 42, 20000);
    add_synth(*bench, exit_code, 120, 10000);
    add_scale(*bench, exit_code);
    add_crowd_quality(*bench, exit_code);
    add_steersuite(*bench, exit_code);
}

}  // namespace

void add_bench_commands(CLI::App& app, int& exit_code) { add_bench(app, exit_code); }

}  // namespace mobb::app
