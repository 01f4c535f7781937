// The shipped scenarios: each read and run to its time limit (the smoke run), and each must pass -
// every agent at its goal in time, no contact at any frame (checked on the record's samples).
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <limits>

#include <nlohmann/json.hpp>

#include "committed_graph.h"
#include "files.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/sim/crowd.h"

namespace mobb::crowd {
namespace {

const MotionGraph& graph() { return test::committed_graph(); }

TEST(Scenario, ShipsTheTestCases) {
    const auto files = scenario_files(default_scenario_folder());
    std::vector<std::string> names;
    for (const std::string& f : files) names.push_back(load_scenario(f).name);
    for (const char* n :
         {"oncoming", "crossing", "four_way", "hallway_two_way", "doorway_two_way", "circle_20", "bottleneck",
          "random_obstacles", "oncoming_obstacle", "crossing_obstacle", "three_way", "fan_out", "hallway_one_way",
          "circle_pillar", "l_walls_60", "evacuation_exit", "fan_in", "fan_in_exit", "waypoints"})
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
    // Every agent that stays comes to stand at its last goal in time: from some frame before the time
    // limit it stays within the goal radius to the end (it stops inside it by the idle clips' sway).
    // Every agent that leaves has left, within the goal radius of its last goal.
    for (const AgentTrack& t : run.record.tracks) {
        ASSERT_FALSE(t.goals.empty());
        const auto& goal = t.goals.back();
        const auto within = [&](std::size_t f) {
            return std::hypot(t.samples[f][1] - goal[0], t.samples[f][2] - goal[1]) < 1.0;
        };
        if (t.at_goal == AtGoal::Leave) {
            ASSERT_TRUE(t.left_frame) << s.name << ": an agent that should leave stays";
            EXPECT_EQ(std::int64_t(t.samples.size()), *t.left_frame);
            EXPECT_TRUE(within(t.samples.size() - 1)) << s.name;
            continue;
        }
        EXPECT_FALSE(t.left_frame);
        std::size_t settled = t.samples.size();
        while (settled > 0 && within(settled - 1)) --settled;
        ASSERT_LT(settled, t.samples.size()) << s.name << ": an agent ends outside its goal radius";
        EXPECT_LT(t.samples[settled][0], s.time_limit) << s.name;
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

// Every numeric field: non-finite, out of order, negative, past the time limit or outside the world.
TEST(Scenario, EveryNumericFieldIsChecked) {
    const nlohmann::json ok = nlohmann::json::parse(R"({"world": [0, 0, 10, 10], "time_limit": 10,
        "obstacles": [{"rectangle": [4, 4, 5, 5]}, {"polygon": [[1, 8], [2, 9]]}],
        "agents": [{"start": [1, 1], "heading": 90, "start_time": 2, "goal": [8, 8]}]})");
    const auto error_after = [&](const std::function<void(nlohmann::json&)>& edit) {
        nlohmann::json j = ok;
        edit(j);
        try {
            parse_scenario(j, "s.json");
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error_after([](nlohmann::json&) {}), "");
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    using Edit = std::function<void(nlohmann::json&)>;
    // One case a line: clang-format 14 breaks up a short lambda that holds a braced list.
    // clang-format off
    const std::vector<std::pair<Edit, std::string>> cases = {
        {[](nlohmann::json& j) { j["world"] = {5, 0, 5, 10}; }, "s.json.world: "},
        {[](nlohmann::json& j) { j["world"] = {6, 0, 5, 10}; }, "s.json.world: "},
        {[](nlohmann::json& j) { j["world"] = {0, 10, 10, 0}; }, "s.json.world: "},
        {[&](nlohmann::json& j) { j["world"][2] = inf; }, "s.json.world[2]: expected a finite number"},
        {[&](nlohmann::json& j) { j["world"][1] = nan; }, "s.json.world[1]: expected a finite number"},
        {[](nlohmann::json& j) { j["world"][0] = "0"; }, "s.json.world[0]: expected a finite number"},
        {[](nlohmann::json& j) { j["world"] = {0, 0, 2000, 10}; }, "s.json.world: at most 1000 m a side"},
        {[](nlohmann::json& j) { j["world"] = {-1e300, 0, 10, 10}; }, "s.json.world[0]: farther than"},
        {[](nlohmann::json& j) { j["time_limit"] = 0; }, "s.json.time_limit: must be positive"},
        {[](nlohmann::json& j) { j["time_limit"] = -10; }, "s.json.time_limit: must be positive"},
        {[&](nlohmann::json& j) { j["time_limit"] = inf; }, "s.json.time_limit: expected a finite number"},
        {[](nlohmann::json& j) { j["time_limit"] = 1e9; }, "s.json.time_limit: at most"},
        {[](nlohmann::json& j) { j["time_limit"] = "10"; }, "s.json.time_limit: expected a finite number"},
        {[](nlohmann::json& j) { j["agents"][0]["start_time"] = -1; }, "s.json.agents[0].start_time: "},
        {[](nlohmann::json& j) { j["agents"][0]["start_time"] = 10; }, "s.json.agents[0].start_time: "},
        {[&](nlohmann::json& j) { j["agents"][0]["start_time"] = nan; }, "s.json.agents[0].start_time: "},
        {[&](nlohmann::json& j) { j["agents"][0]["heading"] = inf; }, "s.json.agents[0].heading: "},
        {[](nlohmann::json& j) { j["agents"][0]["heading"] = "north"; }, "s.json.agents[0].heading: "},
        {[&](nlohmann::json& j) { j["agents"][0]["start"][0] = nan; }, "s.json.agents[0].start[0]: "},
        {[](nlohmann::json& j) { j["agents"][0]["start"] = {-1, 1}; }, "s.json.agents[0].start: outside the world"},
        {[&](nlohmann::json& j) { j["agents"][0]["goal"][1] = -inf; }, "s.json.agents[0].goal[1]: "},
        {[](nlohmann::json& j) { j["agents"][0]["goal"] = {8}; }, "s.json.agents[0].goal: expected 2 numbers"},
        {[](nlohmann::json& j) { j["obstacles"][0]["rectangle"] = {5, 4, 4, 5}; }, "s.json.obstacles[0].rectangle: "},
        {[](nlohmann::json& j) { j["obstacles"][0]["rectangle"] = {4, 4, 5, 4}; }, "s.json.obstacles[0].rectangle: "},
        {[&](nlohmann::json& j) { j["obstacles"][0]["rectangle"][3] = nan; }, "s.json.obstacles[0].rectangle[3]: "},
        {[](nlohmann::json& j) { j["obstacles"][0]["rectangle"] = {8, 8, 12, 9}; },
         "s.json.obstacles[0]: vertex 1 lies outside the world"},
        {[&](nlohmann::json& j) { j["obstacles"][1]["polygon"][1][0] = inf; }, "s.json.obstacles[1].polygon[1][0]: "},
        {[](nlohmann::json& j) { j["obstacles"][1]["polygon"][0] = {-3, 8}; },
         "s.json.obstacles[1]: vertex 0 lies outside the world"},
    };
    // clang-format on
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const std::string e = error_after(cases[k].first);
        EXPECT_EQ(e.rfind(cases[k].second, 0), 0u) << "case " << k << ": " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
}

TEST(Scenario, OptionsRunItsAgentsWithGoals) {
    const Scenario s = parse_scenario(
        nlohmann::json::parse(
            R"({"world": [0, 0, 20, 10], "time_limit": 16, "agents": [{"start": [2, 5], "goal": [18, 5], "start_time": 1.5}]})"),
        "s");
    const CrowdOptions o = scenario_options(s);
    EXPECT_EQ(o.select, Selection::Goal);
    EXPECT_EQ(o.seconds, 16);
    ASSERT_EQ(o.placed.size(), 1u);
    EXPECT_NEAR(o.placed[0].start.theta, 0.0, 1e-12) << "heading defaults to facing the goal";
    const CrowdRun r = run_crowd(graph(), NarrowPhase::sweep(graph()), o);
    const auto& samples = r.record.tracks[0].samples;
    // It stands at its start until its start time, then walks to its goal and stops there.
    EXPECT_LT(std::hypot(samples[40][1] - 2, samples[40][2] - 5), 0.3);
    EXPECT_LT(std::hypot(samples.back()[1] - 18, samples.back()[2] - 5), 1.0);
}

}  // namespace
}  // namespace mobb::crowd
