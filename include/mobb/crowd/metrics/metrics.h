// How good a crowd run is, from its record alone (independent of the trees and the planner): collisions,
// how agents moved and waited, goals, and SteerSuite's composite scores. A crowd that stands still avoids
// trivially, so speed and idle time are reported beside collisions.
#pragma once
#include <cstdint>
#include <string>

#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/record/record.h"

namespace mobb::crowd {

struct CrowdMetrics {
    // Choices and collisions (contacts: agent pairs x frames, checked on the samples, frame_contacts()).
    std::uint64_t choice_points = 0, fallbacks = 0;
    double fallback_share = 0;  ///< fallbacks / choice points
    std::uint64_t contacts = 0, contacts_outside_fallbacks = 0;
    double max_penetration = 0;           ///< metres: the deepest contact, r_a + r_b - |p_a - p_b|
    std::uint64_t samples_outside = 0;    ///< agent samples whose root is outside the world rectangle
    std::uint64_t obstacle_contacts = 0;  ///< agent samples whose disk overlaps a wall or an obstacle
    // Motion: ground speed from the root's path; idle where it moves less than kIdleSpeed over kIdleWindow.
    double mean_speed = 0;    ///< m/s: path length / time, mean over agents
    double graph_speed = 0;   ///< m/s: the graph's clips' path length / duration, mean over clips
    double speed_ratio = 0;   ///< mean_speed / graph_speed
    double idle_share = 0;    ///< of agent time (an agent at its goal no longer counts)
    double longest_idle = 0;  ///< seconds: the longest idle stretch of any agent
    // Goals (agents with one or a sequence).
    int goal_agents = 0;
    int reached = 0;  ///< within the goal radius of each of its goals in turn, at some frames
    int left = 0;     ///< of them, left the run at the last (AtGoal::Leave)
    double mean_time_to_goal = 0, max_time_to_goal = 0;  ///< seconds to the last goal, over the agents that reached it
    /// Path length to the last goal / the straight lines from the start through the goals, mean over them.
    double path_ratio = 0;
    double walking_speed = 0;  ///< m/s: graph_walking_speed()
    /// Time to the last goal over the straight lines' time at walking_speed, mean over the agents that reached it.
    double time_ratio = 0;
    bool passed = false;  ///< every goal agent reached its goal and no contact at any frame
    // SteerSuite's benchmark scores (steerlib/src/CompositeTechnique01.cpp, CompositeTechnique02.cpp), lower
    // is better, on the tracks resampled to its 20 frames per second: Composite01 = 50 x mean unique
    // collisions (counted by both agents) + mean time enabled (to the goal, or the run) + mean sum over
    // frames of |v|^2 / 2; Composite02 adds the mean sum over frames of |dv| / dt.
    double composite01 = 0, composite02 = 0;

    static constexpr double kIdleSpeed = 0.25;  ///< m/s
    static constexpr double kIdleWindow = 1.0;  ///< seconds, centred on the frame
};

/// The metrics of a run of `graph` (goal radius: metres within which a goal counts as reached).
CrowdMetrics crowd_metrics(const Record& record, const MotionGraph& graph, double goal_radius = 1.0);
/// As one JSON object (the record's "metrics"), and as `mobb crowd` prints them.
std::string metrics_json(const CrowdMetrics& m);
std::string metrics_text(const CrowdMetrics& m);

/// The graph's mean clip speed: root path length over duration, mean over its clips (m/s).
double graph_mean_speed(const MotionGraph& graph);
/// The same over its walking clips alone (ClipKind::Walk; m/s): how fast an agent with a clear way goes.
double graph_walking_speed(const MotionGraph& graph);

}  // namespace mobb::crowd
