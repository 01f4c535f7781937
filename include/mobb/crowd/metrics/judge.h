// The per-agent judge of a goal crowd's run (issues 28 and 45; scripts/judge_scenarios.py judges the same
// from a record file): besides no contact and no disk on a wall or an obstacle (CrowdMetrics), every goal
// agent must come within the goal radius of its last goal by its deadline and stay there to the end of the
// run (or until it leaves the run there). Its deadline: min(time limit, start time + 3 d / 1.3 m/s + 20 s),
// d the straight lines from its start through its goals in turn - three times a person's walk, plus room
// to set off.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/record/record.h"

namespace mobb::crowd {

struct JudgeRule {
    double goal_radius = 1.0;  ///< metres
    double speed = 1.3;        ///< m/s: a person's walking speed (Hoogendoorn and Daamen 2005)
    double factor = 3;         ///< times the straight lines' time at `speed`
    double slack = 20;         ///< seconds added
};

/// Where and when an agent of the run starts (the scenario's AgentSpec): metres, seconds.
struct AgentStart {
    std::array<double, 2> at{};
    double time = 0;
};

struct Verdict {
    int goal_agents = 0;
    int on_time = 0;  ///< within the radius of the last goal by the deadline, and stayed
    int never = 0;    ///< never within the radius of its last goal (after the ones before, in turn)
    int late = 0;     ///< first within it after the deadline
    int strayed = 0;  ///< in time, but out of the circle at some later frame
    bool contacts = false, solids = false;  ///< any agent pair, any disk on a wall or obstacle (CrowdMetrics)
    bool passed = false;
    std::string reason;  ///< the first failure, one line; empty when passed
};

/// Judges `record` (its goal tracks' samples) with `starts` (one per track; empty: each track's first
/// sample at time 0), the run's `time_limit` (seconds) and its metrics (for contacts and solids).
Verdict judge_run(const Record& record, const std::vector<AgentStart>& starts, double time_limit,
                  const CrowdMetrics& metrics, const JudgeRule& rule = {});

}  // namespace mobb::crowd
