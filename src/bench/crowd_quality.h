// The avoiding crowd's quality workload (`mobb bench crowd`): wandering crowds at the paper's density and
// every shipped scenario, several seeds each, with their metrics (mobb/crowd/metrics/metrics.h) and the crowd
// issue's targets: fallbacks, contacts, speed, idle time, scenarios passed, collision-detection cost.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/motion/motion_metrics.h"
#include "targets.h"

namespace mobb::bench {

struct CrowdQualityOptions {
    std::string graph;
    std::vector<std::string> scenarios;  ///< scenario files
    std::vector<std::uint64_t> seeds = {1, 2, 3};
    /// Wander sizes: agents, world W x H (metres), simulated seconds.
    struct Wander {
        int agents = 100;
        double width = 30, height = 40, seconds = 120;
    };
    std::vector<Wander> wander = {{100, 30, 40, 120}, {1000, 94.9, 126.5, 120}, {10000, 300, 400, 60}};
    int threads = 1;  ///< per run (CD cost is measured on one thread)
    /// Motion metrics (motion_metrics.h: joint jumps and foot sliding, blended and raw) for runs of at most
    /// this many agents: they pose every agent at every frame from the mocap (about 10 s for 1,000 agents x
    /// 120 s on 2 threads; bench/results/crowd.md). 0: none.
    int motion_agents = 1000;
    /// CD microseconds per agent per simulated second of the crowd before the escapes, MOBB tree, at
    /// 10,000 agents on this machine (bench/results/README.md); the cost target is at most twice it.
    double baseline_us = 3.77;
};

struct WanderRow {
    int agents = 0;
    double width = 0, height = 0, seconds = 0;
    std::uint64_t seed = 0;
    crowd::CrowdMetrics metrics;
    std::uint64_t escapes = 0;
    double cd_us_per_agent_second = 0;
    std::optional<crowd::CrowdMotion> motion;
};

struct ScenarioRow {
    std::string name, file;
    int agents = 0;
    double time_limit = 0;
    std::uint64_t seed = 0;
    crowd::CrowdMetrics metrics;
    std::optional<crowd::CrowdMotion> motion;
};

struct CrowdQualityTable {
    std::vector<WanderRow> wander;
    std::vector<ScenarioRow> scenarios;
    std::vector<Target> targets;
    std::map<std::string, std::string> notes;
};

/// Runs the workload; `progress` (may be empty) gets the fraction done.
CrowdQualityTable run_crowd_quality(const CrowdQualityOptions& o, const std::function<void(double)>& progress = {});

std::string crowd_quality_markdown(const CrowdQualityTable& t);
std::string crowd_quality_json(const CrowdQualityTable& t);
/// Bar chart of the idle share of every wander run and of the time to the last goal of every scenario run.
void write_crowd_quality_png(const CrowdQualityTable& t, const std::string& file);

}  // namespace mobb::bench
