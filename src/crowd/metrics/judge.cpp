#include "mobb/crowd/metrics/judge.h"

#include <algorithm>
#include <cmath>

#include "world/planar.h"

namespace mobb::crowd {

namespace {

enum class Goal { OnTime, Never, Late, Strayed };

bool near(const std::array<double, 4>& s, const std::array<double, 2>& g, double radius) {
    return planar_distance(s[1] - g[0], s[2] - g[1]) < radius;  // NaN (left the run): never near
}

// Straight lines from the start through the goals in turn, metres.
double straight(const std::array<double, 2>& start, const std::vector<std::array<double, 2>>& goals) {
    double d = 0;
    std::array<double, 2> at = start;
    for (const auto& g : goals) d += planar_distance(g[0] - at[0], g[1] - at[1]), at = g;
    return d;
}

// One goal agent: each goal within the radius in turn, the last by the deadline and from then on (to
// the end, or to the frame it left).
Goal judge_agent(const AgentTrack& t, const AgentStart& start, double time_limit, double dt, const JudgeRule& rule) {
    const auto& s = t.samples;
    const std::size_t end = std::min(s.size(), std::size_t(t.left_frame.value_or(std::int64_t(s.size()))));
    std::size_t from = 0;
    for (std::size_t k = 0; k + 1 < t.goals.size(); ++k) {
        while (from < end && !near(s[from], t.goals[k], rule.goal_radius)) ++from;
    }
    std::size_t arrival = from;
    while (arrival < end && !near(s[arrival], t.goals.back(), rule.goal_radius)) ++arrival;
    if (arrival >= end) return Goal::Never;
    const double deadline =
        std::min(time_limit, start.time + rule.factor * straight(start.at, t.goals) / rule.speed + rule.slack);
    constexpr double kSlack = 1e-9;  // seconds: frame times are multiples of dt
    if (double(arrival) * dt > deadline + kSlack) return Goal::Late;
    if (t.left_frame) return Goal::OnTime;  // it left the run at its goal: nothing after to stay for
    // It may step out and back in before the deadline; from then on it stays to the end.
    std::size_t settled = end;
    while (settled > arrival && near(s[settled - 1], t.goals.back(), rule.goal_radius)) --settled;
    if (settled == end || double(settled) * dt > deadline + kSlack) return Goal::Strayed;
    return Goal::OnTime;
}

}  // namespace

Verdict judge_run(const Record& record, const std::vector<AgentStart>& starts, double time_limit,
                  const CrowdMetrics& metrics, const JudgeRule& rule) {
    Verdict v;
    v.contacts = metrics.contacts > 0;
    v.solids = metrics.obstacle_contacts > 0;
    for (std::size_t a = 0; a < record.tracks.size(); ++a) {
        const AgentTrack& t = record.tracks[a];
        if (t.goals.empty() || t.samples.empty()) continue;
        ++v.goal_agents;
        const AgentStart start = a < starts.size() ? starts[a] : AgentStart{{t.samples[0][1], t.samples[0][2]}, 0};
        const Goal g = judge_agent(t, start, time_limit, record.dt, rule);
        v.on_time += g == Goal::OnTime, v.never += g == Goal::Never, v.late += g == Goal::Late;
        v.strayed += g == Goal::Strayed;
        if (g != Goal::OnTime && v.reason.empty())
            v.reason = "agent " + std::to_string(a) +
                       (g == Goal::Never  ? " never reached its goal"
                        : g == Goal::Late ? " reached its goal late"
                                          : " left its goal");
    }
    if (v.solids) v.reason = std::to_string(metrics.obstacle_contacts) + " agent frames on walls or obstacles";
    if (v.contacts) v.reason = std::to_string(metrics.contacts) + " contact frames";
    v.passed = !v.contacts && !v.solids && v.on_time == v.goal_agents;
    return v;
}

}  // namespace mobb::crowd
