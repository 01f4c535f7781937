// The shipped scenarios: each read and run to its time limit (the smoke run), and each must pass -
// every agent at its goal in time, no contact at any frame (checked on the record's samples).
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "files.h"
#include "mobb/crowd/metrics.h"
#include "mobb/crowd/scenario.h"

namespace mobb::crowd {
namespace {

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

const MotionGraph& graph() {
    static const MotionGraph g = load_graph(kGraph);
    return g;
}

TEST(Scenario, ShipsTheEightTestCases) {
    const auto files = scenario_files(default_scenario_folder());
    std::vector<std::string> names;
    for (const std::string& f : files) names.push_back(load_scenario(f).name);
    for (const char* n : {"oncoming", "crossing", "four_way", "hallway_two_way", "doorway_two_way", "circle_20",
                          "bottleneck", "random_obstacles"})
        EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
}

class ShippedScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScenario, Passes) {
    const Scenario s = load_scenario(GetParam());
    EXPECT_FALSE(s.source.empty()) << "says what it is modelled on";
    const CrowdRun run = run_crowd(graph(), NarrowPhase::sweep(graph()), scenario_options(s));
    const CrowdMetrics m = crowd_metrics(run.record, graph());
    EXPECT_EQ(m.goal_agents, int(s.agents.size()));
    EXPECT_EQ(m.reached, m.goal_agents) << s.name;
    EXPECT_EQ(frame_contacts(run.record).size(), 0u) << s.name;
    EXPECT_EQ(m.obstacle_contacts, 0u) << s.name;
    EXPECT_TRUE(m.passed) << s.name;
    // Arrived agents stay within the goal radius to the end.
    for (const AgentTrack& t : run.record.tracks) {
        ASSERT_TRUE(t.goal);
        const auto& last = t.samples.back();
        EXPECT_LT(std::hypot(last[1] - (*t.goal)[0], last[2] - (*t.goal)[1]), 1.0 + 0.3) << s.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Shipped, ShippedScenario, ::testing::ValuesIn(scenario_files(default_scenario_folder())),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             std::string n = param.param.substr(param.param.find_last_of('/') + 1);
                             n = n.substr(0, n.size() - 5);
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

std::string error_of(const std::string& text) {
    try {
        parse_scenario(nlohmann::json::parse(text), "s.json");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(Scenario, BadFilesNameThePlace) {
    const std::string agent = R"({"start": [1, 1], "goal": [5, 5]})";
    const std::string ok = R"({"name": "x", "world": [0, 0, 10, 10], "time_limit": 10, "agents": [)" + agent + "]}";
    EXPECT_EQ(error_of(ok), "");
    EXPECT_EQ(
        error_of(R"({"world": [0, 0, 10, 10], "time_limit": 10, "agents": [{"start": [1, 1], "goal": [50, 5]}]})"),
        "s.json.agents[0].goal: outside the world");
    EXPECT_EQ(error_of(R"({"world": [0, 0, 10, 10], "time_limit": 10, "agents": [], "colour": 1})"),
              "s.json.colour: unknown key");
    EXPECT_EQ(error_of(R"({"world": [0, 0, 10], "time_limit": 10, "agents": [)" + agent + "]}"),
              "s.json.world: expected 4 numbers");
    EXPECT_EQ(error_of(R"({"world": [0, 0, 10, 10], "time_limit": -1, "agents": [)" + agent + "]}"),
              "s.json.time_limit: must be positive");
    EXPECT_EQ(
        error_of(R"({"world": [0, 0, 10, 10], "time_limit": 5, "obstacles": [{"polygon": [[1, 1]]}], "agents": [)" +
                 agent + "]}"),
        "s.json.obstacles[0]: expected \"rectangle\" or \"polygon\" (two or more [x, y])");
    const std::string file = test::temp_file("scenario_bad.json");
    std::ofstream(file) << "{ not json";
    try {
        load_scenario(file);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), file + ": not valid JSON");
    }
    std::remove(file.c_str());
}

TEST(Scenario, OptionsRunItsAgentsWithGoals) {
    const Scenario s = parse_scenario(
        nlohmann::json::parse(
            R"({"world": [0, 0, 20, 10], "time_limit": 12, "agents": [{"start": [2, 5], "goal": [18, 5], "start_time": 1.5}]})"),
        "s");
    const CrowdOptions o = scenario_options(s);
    EXPECT_EQ(o.select, Selection::Goal);
    EXPECT_EQ(o.seconds, 12);
    ASSERT_EQ(o.placed.size(), 1u);
    EXPECT_NEAR(o.placed[0].start.theta, 0.0, 1e-12) << "heading defaults to facing the goal";
    const CrowdRun r = run_crowd(graph(), NarrowPhase::sweep(graph()), o);
    const auto& samples = r.record.tracks[0].samples;
    // It stands at its start until its start time, then walks to its goal.
    EXPECT_LT(std::hypot(samples[40][1] - 2, samples[40][2] - 5), 0.3);
    EXPECT_LT(std::hypot(samples.back()[1] - 18, samples.back()[2] - 5), 1.3);
}

}  // namespace
}  // namespace mobb::crowd
