// mobb scenario import: crowd scenarios from other tools' test cases (SteerSuite's XML).
#include <fstream>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "cli.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/scenario/steersuite.h"

namespace mobb::app {

namespace {

void add_import(CLI::App& group, int& exit_code) {
    auto* cmd = group.add_subcommand(
        "import", "Write a SteerSuite test case (XML) as a mobb scenario (JSON); what mobb cannot do goes to stderr");
    auto file = std::make_shared<std::string>();
    auto out_file = std::make_shared<std::string>();
    auto graph = std::make_shared<std::string>();
    auto o = std::make_shared<crowd::ImportOptions>();
    cmd->add_option("FILE", *file, "SteerSuite test case (SteerBenchTestCase XML)")->required();
    cmd->add_option("--out", *out_file, "Scenario JSON to write")->required();
    cmd->add_option("--seed", o->seed, "Seed of random positions, directions, goals and obstacles")
        ->capture_default_str();
    cmd->add_option("--time-limit", o->time_limit, "Seconds (default: estimated from the longest walk)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--at-goal", o->at_goal,
                    "At their last goal agents leave (SteerSuite's semantics, the default) or stay")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, crowd::AtGoal>{{"leave", crowd::AtGoal::Leave}, {"stay", crowd::AtGoal::Stay}}));
    cmd->add_option("--graph", *graph,
                    "Motion graph whose agents must fit (default: assets/graphs/cmu_locomotion.json, as mobb crowd)");
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            // The room agents need comes from the graph `mobb crowd` will run them with.
            const crowd::AgentRoom room =
                crowd::AgentRoom::of(crowd::load_graph(graph->empty() ? crowd::default_graph_file() : *graph));
            const crowd::ImportedScenario imported = crowd::import_steersuite(*file, room, *o);
            for (const std::string& n : imported.notes) std::cerr << "note: " << n << "\n";
            const crowd::Scenario& s = imported.scenario;
            if (s.agents.empty() && imported.case_agents > 0)
                throw InputError(*file + ": no agent mobb can run is left (see the notes): nothing written");
            const std::string text = crowd::scenario_json(s);
            crowd::parse_scenario(nlohmann::json::parse(text), *out_file);  // what mobb crowd reads, or no file
            std::ofstream f(*out_file);
            f << text;
            if (!f) throw InputError(*out_file + ": cannot write");
            const auto count = [](std::size_t n, const char* what) {
                return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
            };
            out << *out_file << ": scenario " << s.name << ", " << count(s.agents.size(), "agent") << ", "
                << count(s.world.obstacles.size(), "obstacle") << ", " << s.world.width() << " x " << s.world.height()
                << " m, time limit " << s.time_limit << " s\n";
        });
    });
}

}  // namespace

void add_scenario_commands(CLI::App& app, int& exit_code) {
    auto* group = app.add_subcommand("scenario", "Crowd scenarios (mobb crowd --scenario)");
    group->require_subcommand(1);
    add_import(*group, exit_code);
}

}  // namespace mobb::app
