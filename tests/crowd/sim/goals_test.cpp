// What goal agents do with their goals (crowd.h, AgentSpec): goal sequences reached in turn, and agents
// that leave the run at their last goal - their track ends, their ground is free for the others - or
// stay there; and how records, metrics and scenario files carry them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>

#include "committed_graph.h"
#include "files.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/sim/crowd.h"

namespace mobb::crowd {
namespace {

const MotionGraph& graph() { return test::committed_graph(); }

CrowdRun run_goals(const std::vector<AgentSpec>& agents, double seconds) {
    CrowdOptions o;
    o.world = {0, 0, 24, 24, true, {}};
    o.placed = agents;
    o.agents = int(agents.size());
    o.seconds = seconds;
    o.select = Selection::Goal;
    return run_crowd(graph(), NarrowPhase::sweep(graph()), o);
}

AgentSpec spec(double x, double y, std::vector<std::array<double, 2>> goals, AtGoal at_goal = AtGoal::Stay) {
    AgentSpec a;
    a.start = {x, y, std::atan2(goals[0][1] - y, goals[0][0] - x), 0};
    a.goals = std::move(goals);
    a.at_goal = at_goal;
    return a;
}

// The first frame from `from` on at which the track is within `radius` of `goal`, or -1.
std::int64_t first_within(const AgentTrack& t, const std::array<double, 2>& goal, std::size_t from, double radius) {
    for (std::size_t f = from; f < t.samples.size(); ++f)
        if (std::hypot(t.samples[f][1] - goal[0], t.samples[f][2] - goal[1]) < radius) return std::int64_t(f);
    return -1;
}

TEST(Goals, ASequenceIsReachedInTurn) {
    // Out east, up north, back west: the last goal is nearer the start than the first two.
    const std::vector<std::array<double, 2>> goals{{18, 5}, {18, 17}, {6, 17}};
    const CrowdRun r = run_goals({spec(4, 5, goals)}, 60);
    const AgentTrack& t = r.record.tracks[0];
    EXPECT_EQ(t.goals, goals);
    std::size_t from = 0;
    for (const auto& g : goals) {
        const std::int64_t f = first_within(t, g, from, 1.0);
        ASSERT_GE(f, 0) << "goal (" << g[0] << ", " << g[1] << ") not reached after frame " << from;
        from = std::size_t(f);
    }
    // It stands at the last goal to the end, and the metrics count it reached at that frame.
    EXPECT_LT(std::hypot(t.samples.back()[1] - 6, t.samples.back()[2] - 17), 1.0);
    const CrowdMetrics m = crowd_metrics(r.record, graph());
    EXPECT_EQ(m.reached, 1);
    EXPECT_EQ(m.left, 0);
    EXPECT_NEAR(m.max_time_to_goal, double(from) * r.record.dt, 1e-9);
    // Through the goals, not straight to the last (12.2 m, a third of the 38 m through them): the path
    // is about as long as the straight lines through the goals (shorter where it cuts a goal's disk).
    EXPECT_GT(m.path_ratio, 0.8);
    EXPECT_LT(m.path_ratio, 1.5);
}

TEST(Goals, AnAgentThatLeavesEndsItsTrackThere) {
    const CrowdRun r = run_goals({spec(4, 12, {{16, 12}}, AtGoal::Leave)}, 30);
    const AgentTrack& t = r.record.tracks[0];
    ASSERT_TRUE(t.left_frame);
    EXPECT_EQ(std::int64_t(t.samples.size()), *t.left_frame);
    EXPECT_LT(*t.left_frame, r.record.frames);
    EXPECT_LT(std::hypot(t.samples.back()[1] - 16, t.samples.back()[2] - 12), 1.0);
    // Its clips end where its track does, and no choice point of it comes after.
    const PlacedClip& last = t.clips.back();
    EXPECT_EQ(last.start + std::int64_t(graph().clips[std::size_t(last.clip)].path.size()), *t.left_frame);
    for (const ChoicePoint& c : r.record.choices) EXPECT_LT(c.frame, *t.left_frame);
    const CrowdMetrics m = crowd_metrics(r.record, graph());
    EXPECT_EQ(m.reached, 1);
    EXPECT_EQ(m.left, 1);
    EXPECT_TRUE(m.passed);
}

// Two agents with one exit: the first leaves there; the second, starting later, reaches the same point
// and stays - which it could not if the first still held its ground (two held disks cannot overlap).
TEST(Goals, AnAgentThatLeftHoldsNoGround) {
    AgentSpec late = spec(4, 16, {{16, 12}});
    late.start_time = 6;
    const CrowdRun r = run_goals({spec(4, 8, {{16, 12}}, AtGoal::Leave), late}, 50);
    const auto& first = r.record.tracks[0];
    const auto& second = r.record.tracks[1];
    ASSERT_TRUE(first.left_frame);
    EXPECT_FALSE(second.left_frame);
    const double dt = r.record.dt;
    EXPECT_LT(std::hypot(second.samples.back()[1] - 16, second.samples.back()[2] - 12), 1.0);
    const std::int64_t arrived = first_within(second, {16, 12}, 0, 1.0);
    ASSERT_GE(arrived, 0);
    EXPECT_GT(arrived, *first.left_frame) << "the second came after the first left (" << double(arrived) * dt << " s)";
    EXPECT_EQ(frame_contacts(r.record).size(), 0u);
    // The same pair, both staying: the second cannot stand where the first stands.
    const CrowdRun both = run_goals({spec(4, 8, {{16, 12}}), late}, 50);
    const auto& s = both.record.tracks[1].samples.back();
    EXPECT_GE(std::hypot(s[1] - 16, s[2] - 12), 0.5);
}

TEST(Goals, RecordsCarryGoalsAndLeaving) {
    AgentSpec seq = spec(4, 4, {{12, 4}, {12, 12}});
    const CrowdRun r = run_goals({seq, spec(4, 20, {{14, 20}}, AtGoal::Leave)}, 30);
    const std::string file = test::temp_file("goals_record.json");
    std::ofstream(file) << record_to_text(r.record, summary_json(r.summary));
    const Record back = load_record(file);
    ASSERT_EQ(back.tracks.size(), 2u);
    EXPECT_EQ(back.tracks[0].goals, seq.goals);
    EXPECT_EQ(back.tracks[0].at_goal, AtGoal::Stay);
    EXPECT_FALSE(back.tracks[0].left_frame);
    EXPECT_EQ(back.tracks[1].at_goal, AtGoal::Leave);
    EXPECT_EQ(back.tracks[1].left_frame, r.record.tracks[1].left_frame);
    EXPECT_EQ(back.tracks[1].samples.size(), r.record.tracks[1].samples.size());
    // What the file says is checked: a left frame for an agent that stays, samples past it.
    const nlohmann::json written = nlohmann::json::parse(test::slurp(file));
    const auto error_after = [&](const std::function<void(nlohmann::json&)>& edit) {
        nlohmann::json j = written;
        edit(j);
        std::ofstream(file) << j.dump();
        try {
            load_record(file);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error_after([](nlohmann::json& j) { j["tracks"][0]["left_frame"] = 10; }),
              file + ": tracks[0].left_frame: only an agent that leaves has one");
    EXPECT_NE(error_after([](nlohmann::json& j) {
                  j["tracks"][1]["samples"].push_back({0, 0, 0, 0});
              }).find("tracks[1].samples: "),
              std::string::npos);
    EXPECT_EQ(error_after([](nlohmann::json& j) { j["tracks"][1]["at_goal"] = "wait"; }),
              file + ": tracks[1].at_goal: expected \"stay\" or \"leave\"");
    EXPECT_EQ(error_after([](nlohmann::json& j) {
                  j["tracks"][0]["goal"] = {1, 1};
              }),
              file + ": tracks[0]: \"goal\" or \"goals\", not both");
    std::remove(file.c_str());
}

std::string scenario_error(const std::string& agents, const std::string& extra = "") {
    try {
        parse_scenario(nlohmann::json::parse(R"({"world": [0, 0, 10, 10], "time_limit": 10, )" + extra +
                                             R"("agents": [)" + agents + "]}"),
                       "s.json");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(Goals, ScenariosSayGoalsAndWhatAgentsDoThere) {
    const Scenario s = parse_scenario(nlohmann::json::parse(R"({"world": [0, 0, 10, 10], "time_limit": 10,
        "at_goal": "leave", "agents": [{"start": [1, 1], "goals": [[5, 1], [5, 5]]},
                                       {"start": [1, 8], "goal": [8, 8], "at_goal": "stay"}]})"),
                                      "s.json");
    EXPECT_EQ(s.at_goal, AtGoal::Leave);
    EXPECT_EQ(s.agents[0].goals, (std::vector<std::array<double, 2>>{{5, 1}, {5, 5}}));
    EXPECT_EQ(s.agents[0].at_goal, AtGoal::Leave);
    EXPECT_NEAR(s.agents[0].start.theta, 0, 1e-12);  // facing the first goal
    EXPECT_EQ(s.agents[1].at_goal, AtGoal::Stay);
    const Scenario back = parse_scenario(nlohmann::json::parse(scenario_json(s)), "back");
    EXPECT_EQ(back.at_goal, AtGoal::Leave);
    EXPECT_EQ(back.agents[0].goals, s.agents[0].goals);
    EXPECT_EQ(back.agents[1].at_goal, AtGoal::Stay);
    EXPECT_EQ(scenario_error(R"({"start": [1, 1], "goal": [5, 5], "goals": [[5, 5]]})"),
              "s.json.agents[0]: needs \"goal\" or \"goals\" (not both)");
    EXPECT_EQ(scenario_error(R"({"start": [1, 1]})"), "s.json.agents[0]: needs \"goal\" or \"goals\" (not both)");
    EXPECT_EQ(scenario_error(R"({"start": [1, 1], "goals": []})"),
              "s.json.agents[0].goals: expected a non-empty array of [x, y]");
    EXPECT_EQ(scenario_error(R"({"start": [1, 1], "goals": [[5, 5], [50, 5]]})"),
              "s.json.agents[0].goals[1]: outside the world");
    EXPECT_EQ(scenario_error(R"({"start": [1, 1], "goal": [5, 5], "at_goal": "wait"})"),
              "s.json.agents[0].at_goal: expected \"stay\" or \"leave\"");
    EXPECT_EQ(scenario_error(R"({"start": [1, 1], "goal": [5, 5]})", R"("at_goal": 1, )"),
              "s.json.at_goal: expected \"stay\" or \"leave\"");
}

// A goal agent may start with room to stand by a wall (its held ground keeps as much from walls), not only
// with room to turn round: 0.7 m from the west wall, facing along it, it runs and reaches its goal; 0.5 m
// from it, where it could not stand, the run is refused in one line.
TEST(Goals, AStartByAWallNeedsRoomToStandNotToTurn) {
    AgentSpec by_wall = spec(0.7, 4, {{0.9, 20}});
    by_wall.start.theta = std::atan2(1.0, 0.0);  // north, along the wall x = 0
    const CrowdRun r = run_goals({by_wall}, 40);
    EXPECT_GE(first_within(r.record.tracks[0], {0.9, 20}, 0, 1.0), 0);
    const CrowdMetrics m = crowd_metrics(r.record, graph());
    EXPECT_EQ(m.obstacle_contacts, 0u);
    AgentSpec too_near = by_wall;
    too_near.start.x = 0.5;
    try {
        run_goals({too_near}, 5);
        FAIL() << "a start 0.5 m from a wall ran";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("agent 0 starts within 0.58"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace mobb::crowd
