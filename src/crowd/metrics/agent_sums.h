// What each agent adds to a run's metrics, and the means they end in. One home for crowd_metrics (a whole
// record, metrics.cpp) and MetricsStream (frames as they come, metrics_stream.cpp), which must agree to the
// last bit: both add their agents here, in agent order. Private to src/crowd.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "mobb/crowd/metrics/metrics.h"

namespace mobb::crowd {

/// One agent's share of the metrics.
struct AgentOutcome {
    double speed = 0;           ///< m/s: its path's length over its time in the run
    std::int64_t reached = -1;  ///< the frame it reached its last goal; -1: never
    std::int64_t counted = 0;   ///< frames its idle share counts: until it reached, else all it has
    double longest_idle = 0;    ///< seconds
    bool has_goals = false, left = false;
    double to_goal = 0;   ///< metres walked before it reached
    double straight = 0;  ///< metres: the straight lines from its start through its goals (when reached)
    double enabled = 0;   ///< seconds it counts for SteerSuite's composites: until it reached, else the run
    double collisions = 0, energy = 0, acceleration = 0;  ///< SteerSuite's composite terms
};

class AgentSums {
public:
    void add(const AgentOutcome& a, double dt, CrowdMetrics& m) {
        speed_ += a.speed;
        counted_ += std::uint64_t(a.counted);
        m.longest_idle = std::max(m.longest_idle, a.longest_idle);
        if (a.has_goals) ++m.goal_agents;
        if (a.reached >= 0) {
            ++m.reached;
            m.left += a.left;
            time_ += double(a.reached) * dt;
            m.max_time_to_goal = std::max(m.max_time_to_goal, double(a.reached) * dt);
            ratio_ += a.straight > 0 ? a.to_goal / a.straight : 1.0;
            time_ratio_ += a.straight > 0 ? double(a.reached) * dt * m.walking_speed / a.straight : 1.0;
        }
        c1_ += 50.0 * a.collisions + a.enabled + a.energy;
        c2_ += a.acceleration;
    }
    /// The means over `agents` agents; `idle`: idle frames of them all.
    void finish(std::size_t agents, std::uint64_t idle, CrowdMetrics& m) const {
        const double n = double(std::max<std::size_t>(1, agents));
        m.mean_speed = speed_ / n;
        m.speed_ratio = m.graph_speed > 0 ? m.mean_speed / m.graph_speed : 0.0;
        m.idle_share = counted_ ? double(idle) / double(counted_) : 0.0;
        m.mean_time_to_goal = m.reached ? time_ / m.reached : 0.0;
        m.path_ratio = m.reached ? ratio_ / m.reached : 0.0;
        m.time_ratio = m.reached ? time_ratio_ / m.reached : 0.0;
        m.passed = m.reached == m.goal_agents && m.contacts == 0 && m.obstacle_contacts == 0;
        m.composite01 = c1_ / n;
        m.composite02 = (c1_ + c2_) / n;
    }

private:
    std::uint64_t counted_ = 0;
    double speed_ = 0, time_ = 0, ratio_ = 0, time_ratio_ = 0, c1_ = 0, c2_ = 0;
};

}  // namespace mobb::crowd
