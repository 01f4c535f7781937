// Small crowds the record tests share (record_file, record_stream, record_reader): between them they fill
// every field of a record, and a run comes with its summary and metrics as a record file holds them.
// Needs MOBB_SOURCE_DIR and mobb_crowd.
#pragma once
#include <string>
#include <utility>

#include "committed_graph.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/sim/crowd.h"

namespace mobb::test {

inline const std::string kFanInExit = std::string(MOBB_SOURCE_DIR) + "/assets/scenarios/fan_in_exit.json";

/// 30 agents choosing at random in a 14 x 14 m world for 8 s: they touch, some deeply.
inline crowd::CrowdOptions random_mode_crowd() {
    crowd::CrowdOptions o;
    o.agents = 30;
    o.seconds = 8;
    o.seed = 4;
    o.select = crowd::Selection::Random;
    o.world.x1 = 14;
    o.world.y1 = 14;
    return o;
}

/// `agents` avoiding agents in a 9 x 11 m room beside a 1 x 2 m obstacle for 6 s: queries against agents,
/// the ground others hold, walls and the obstacle.
inline crowd::CrowdOptions crowd_beside_obstacle(int agents) {
    crowd::CrowdOptions o;
    o.agents = agents;
    o.seconds = 6;
    o.seed = 9;
    o.world.x1 = 9;
    o.world.y1 = 11;
    o.world.obstacles.push_back(crowd::Polygon::rectangle(3, 4, 4, 6));
    return o;
}

/// fan_in_exit.json for 20 s: goal sequences reached in turn, agents that leave at their last goal.
inline crowd::CrowdOptions leaving_crowd() {
    crowd::CrowdOptions o = crowd::scenario_options(crowd::load_scenario(kFanInExit));
    o.seconds = 20;
    return o;
}

/// A run as a record file holds it: the record, its summary and metrics as JSON text, and its options.
struct WrittenRun {
    crowd::Record record;
    std::string summary, metrics;
    crowd::CrowdOptions options;
};

/// `o` run on the committed graph with the sweep; `scenario` names the record's scenario ("" for none).
inline WrittenRun run_written(const crowd::CrowdOptions& o, const std::string& scenario = "") {
    const crowd::MotionGraph& g = committed_graph();
    crowd::CrowdRun run = crowd::run_crowd(g, crowd::NarrowPhase::sweep(g), o);
    run.record.scenario = scenario;
    const std::string metrics = crowd::metrics_json(crowd::crowd_metrics(run.record, g, o.goal_radius));
    return {std::move(run.record), crowd::summary_json(run.summary), metrics, o};
}

/// The scenario name fan_in_exit.json gives its records.
inline std::string fan_in_exit_name() { return crowd::load_scenario(kFanInExit).name; }

}  // namespace mobb::test
