// The per-agent judge (judge.h) on records made by hand: each way an agent can fail its goal, and the
// contacts and solids the metrics report.
#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "mobb/crowd/metrics/judge.h"

namespace mobb::crowd {
namespace {

// One agent starting at (0, 0) at time 0 with a goal at (10, 0): deadline min(limit, 3 x 10 / 1.3 + 20) =
// 43.08 s; 60 s of frames at 10 Hz, x(t) given.
Record one_agent(const std::function<double(double)>& x) {
    Record r;
    r.dt = 0.1;
    r.frames = 600;
    r.tracks.resize(1);
    r.tracks[0].goals = {{10, 0}};
    for (int f = 0; f < r.frames; ++f) r.tracks[0].samples.push_back({f * r.dt, x(f * r.dt), 0, 0.3});
    return r;
}

Verdict judge(const Record& r, double limit = 60) { return judge_run(r, {}, limit, CrowdMetrics{}); }

TEST(Judge, OnTimeAndStaying) {
    const Verdict v = judge(one_agent([](double t) { return std::min(10.0, 0.5 * t); }));  // there at 20 s
    EXPECT_TRUE(v.passed) << v.reason;
    EXPECT_EQ(v.goal_agents, 1);
    EXPECT_EQ(v.on_time, 1);
}

TEST(Judge, LateNeverAndTheTimeLimit) {
    const Record slow = one_agent([](double t) { return std::min(10.0, 0.2 * t); });  // within 1 m at 45 s
    EXPECT_EQ(judge(slow).late, 1);
    EXPECT_EQ(judge(slow).reason, "agent 0 reached its goal late");
    EXPECT_EQ(judge(one_agent([](double) { return 0.0; })).never, 1);
    // A time limit below the 43 s deadline is the deadline.
    EXPECT_EQ(judge(one_agent([](double t) { return std::min(10.0, 0.3 * t); }), 25).late, 1);  // 30 s
    EXPECT_TRUE(judge(one_agent([](double t) { return std::min(10.0, 0.3 * t); }), 60).passed);
}

TEST(Judge, StepsOutAndBackBeforeTheDeadlinePassesLaterOrAtTheEndFails) {
    // Within 1 m from 18 s, out at 25-30 s (x = 8.5), back and staying: settled at 30 s < 43 s.
    const auto back = [](double t) { return t >= 25 && t < 30 ? 8.5 : std::min(10.0, 0.5 * t); };
    EXPECT_TRUE(judge(one_agent(back)).passed);
    // Out from 50 s on (after the deadline): strayed.
    const Verdict late_out = judge(one_agent([](double t) { return t >= 50 ? 8.5 : std::min(10.0, 0.5 * t); }));
    EXPECT_EQ(late_out.strayed, 1);
    EXPECT_FALSE(late_out.passed);
}

TEST(Judge, LeftTheRunAtItsGoalAndGoalsInTurn) {
    Record left = one_agent([](double t) { return 0.5 * t; });
    left.tracks[0].samples.resize(200);  // left at 20 s, within 1 m of (10, 0) from 18 s
    left.tracks[0].left_frame = 200;
    EXPECT_TRUE(judge(left).passed);
    // Goals in turn: (4, 3) first, then (10, 0). Walking straight along y = 0 never comes within 1 m of
    // (4, 3), so the last goal does not count.
    Record turn = one_agent([](double t) { return std::min(10.0, 0.5 * t); });
    turn.tracks[0].goals = {{4, 3}, {10, 0}};
    EXPECT_EQ(judge(turn).never, 1);
    // Through (4, 0.5) it does: deadline 3 x (4.03 + 6.02) / 1.3 + 20 = 43.2 s.
    turn.tracks[0].goals = {{4, 0.5}, {10, 0}};
    EXPECT_TRUE(judge(turn).passed);
}

TEST(Judge, ContactsSolidsAndStarts) {
    const Record r = one_agent([](double t) { return std::min(10.0, 0.5 * t); });
    CrowdMetrics m;
    m.obstacle_contacts = 3;
    EXPECT_FALSE(judge_run(r, {}, 60, m).passed);
    EXPECT_EQ(judge_run(r, {}, 60, m).reason, "3 agent frames on walls or obstacles");
    m.contacts = 2;
    EXPECT_EQ(judge_run(r, {}, 60, m).reason, "2 contact frames");
    // Starting at 30 s moves the deadline to 73 s: the same late walk passes.
    const Record slow = one_agent([](double t) { return std::min(10.0, 0.2 * t); });
    EXPECT_TRUE(judge_run(slow, {{{0, 0}, 30}}, 100, CrowdMetrics{}).passed);
    // A wanderer (no goal) is not judged.
    Record wander = r;
    wander.tracks[0].goals.clear();
    EXPECT_EQ(judge(wander).goal_agents, 0);
    EXPECT_TRUE(judge(wander).passed);
}

}  // namespace
}  // namespace mobb::crowd
