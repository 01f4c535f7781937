// The pose of agent K at time t (agent_pose.h) and what `mobb export-crowd` writes from it (issue 30):
// roots on the record's tracks, every joint of the blended pose inside the disk r(t) the collision answers
// used, no pops at clip starts, the glTF re-read with tinygltf (one skin per agent, roots on the tracks
// within 1 mm at every frame), the BVH re-read with mobb's own loader (the agent's track within 1 mm), and
// bad ranges and files refused without leaving a file.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "data.h"
#include "files.h"
#include "mobb/crowd/collision/narrow_phase.h"
#include "mobb/crowd/motion/crowd_export.h"
#include "mobb/crowd/motion/motion_metrics.h"
#include "mobb/crowd/sim/crowd.h"

namespace mobb::crowd {
namespace {

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

std::shared_ptr<MotionGraph> graph() {
    static const auto g = std::make_shared<MotionGraph>(load_graph(kGraph));
    return g;
}

// A wandering crowd of 12 agents in a walled 12 x 12 m room.
CrowdOptions room_crowd(double seconds) {
    CrowdOptions o;
    o.agents = 12;
    o.seconds = seconds;
    o.seed = 11;
    o.world.x1 = 12;
    o.world.y1 = 12;
    return o;
}

// The room's crowd for 30 s (some 300 clip starts).
const Record& record() {
    static const Record r = run_crowd(*graph(), NarrowPhase::sweep(*graph()), room_crowd(30)).record;
    return r;
}

// A poser of the test record; `lock` sets FootLock's other fields (glides, lift).
CrowdPoser poser(PoseBlend blend = {}, RigJoints joints = RigJoints::All, bool lock_feet = true, bool carry = true,
                 FootLock lock = {}) {
    lock.on = lock_feet;
    lock.carry = carry;
    return CrowdPoser(record(), std::make_shared<PoseSources>(graph()), joints, blend, lock);
}

// Where the graph puts agent a's root at frame k of record r: its clip's root there, placed (for disks
// centred on the body, off their centres).
glm::dvec2 root_of_agent(const Record& r, const MotionGraph& g, int a, std::int64_t k) {
    AgentClipAt at;
    if (!agent_clip_at(r, g, a, k, at)) return glm::dvec2(std::nan(""));
    return placed_root(g.clips[std::size_t(at.placed->clip)], Rigid2::of(at.placed->place),
                       std::size_t(k - at.placed->start));
}

TEST(AgentPose, RootsOnTheTrackAndJointsInsideTheDisk) {
    MOBB_REQUIRE_MOCAP();
    for (const double window : {0.0, 0.25}) {
        PoseBlend blend;
        blend.window = window;
        CrowdPoser p = poser(blend);
        EXPECT_EQ(p.rig().parents[0], -1);
        std::vector<glm::dvec3> pose;
        double root_error = 0, outside = -1;
        for (int a = 0; a < int(record().tracks.size()); ++a)
            for (std::int64_t k = 0; k < record().frames; ++k) {
                ASSERT_TRUE(p.pose(a, k, pose)) << "agent " << a << " frame " << k;
                const auto& s = record().tracks[std::size_t(a)].samples[std::size_t(k)];
                const glm::dvec2 root = root_of_agent(record(), *graph(), a, k);
                root_error = std::max(root_error, std::hypot(pose[0].x - root.x, pose[0].y - root.y));
                EXPECT_EQ(pose[0].z, 0.0);
                for (const glm::dvec3& q : pose)
                    outside = std::max(outside, std::hypot(q.x - pose[0].x, q.y - pose[0].y) - s[3]);
            }
        // The graph rounds clip paths to micrometres; the record chains placements in doubles.
        EXPECT_LT(root_error, 1e-4) << "blend " << window;
        // Raw poses: r is the largest joint distance of the same pose (to the graph's rounding); blended
        // ones are held inside it.
        EXPECT_LT(outside, window > 0 ? 1e-9 : 1e-5) << "blend " << window;
    }
}

// Disks centred on the body (assets/graphs/cmu_locomotion_enclosing.json): the root where the clip puts it,
// off the disk's centre, and every joint of the blended, foot-locked pose inside the disk, as with the
// root's disks; held about the root instead, some would not be.
TEST(AgentPose, DisksCentredOnTheBodyHoldTheBlendedPose) {
    MOBB_REQUIRE_MOCAP();
    const auto body = std::make_shared<MotionGraph>(
        load_graph(std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion_enclosing.json"));
    const Record r = run_crowd(*body, NarrowPhase::sweep(*body), room_crowd(10)).record;
    CrowdPoser p(r, std::make_shared<PoseSources>(body), RigJoints::All, PoseBlend{}, FootLock{});
    std::vector<glm::dvec3> pose;
    double root_error = 0, outside = -1, off_centre = 0, outside_about_root = -1;
    for (int a = 0; a < int(r.tracks.size()); ++a)
        for (std::int64_t k = 0; k < r.frames; ++k) {
            ASSERT_TRUE(p.pose(a, k, pose));
            const auto& s = r.tracks[std::size_t(a)].samples[std::size_t(k)];
            const glm::dvec2 root = root_of_agent(r, *body, a, k);
            root_error = std::max(root_error, std::hypot(pose[0].x - root.x, pose[0].y - root.y));
            off_centre = std::max(off_centre, std::hypot(root.x - s[1], root.y - s[2]));
            for (const glm::dvec3& q : pose) {
                outside = std::max(outside, std::hypot(q.x - s[1], q.y - s[2]) - s[3]);
                outside_about_root = std::max(outside_about_root, std::hypot(q.x - root.x, q.y - root.y) - s[3]);
            }
        }
    EXPECT_LT(root_error, 1e-4);
    EXPECT_GT(off_centre, 0.1) << "metres: the disks are not about the root";
    EXPECT_LT(outside, 1e-5) << "metres: inside, to the graph's rounding of the centre about the root";
    EXPECT_GT(outside_about_root, 0.05) << "a disk this size about the root would not hold the body";
}

TEST(AgentPose, OutsideTheRecordThereIsNoPose) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser p = poser();
    std::vector<glm::dvec3> pose;
    EXPECT_FALSE(p.pose(-1, 0, pose));
    EXPECT_FALSE(p.pose(int(record().tracks.size()), 0, pose));
    EXPECT_FALSE(p.pose(0, -1, pose));
    EXPECT_FALSE(p.pose(0, record().frames, pose));
    EXPECT_FALSE(p.pose_at(0, -0.1, pose));
    EXPECT_TRUE(p.pose_at(0, double(record().frames) * record().dt, pose));
}

TEST(AgentPose, BlendingRemovesThePopsAtClipStarts) {
    MOBB_REQUIRE_MOCAP();
    std::vector<int> agents;
    for (int a = 0; a < int(record().tracks.size()); ++a) agents.push_back(a);
    PoseBlend off;
    off.window = 0;
    CrowdPoser raw = poser(off, RigJoints::All, false), blended = poser();
    const CrowdMotion both = motion_metrics(blended, agents, 0, record().frames, 2);
    const MotionMetrics before = motion_metrics(raw, agents, 0, record().frames).blended, after = both.blended;
    // One posing gives the raw clips' metrics too, as a poser without blending does.
    EXPECT_EQ(both.raw.jump_start.p99, before.jump_start.p99);
    EXPECT_EQ(both.raw.jump_within.median, before.jump_within.median);
    EXPECT_EQ(both.raw.sliding[0].contact, before.sliding[0].contact);
    EXPECT_GT(before.jump_start.count, 200u);
    EXPECT_EQ(before.jump_start.count, after.jump_start.count);
    EXPECT_EQ(before.jump_within.count, after.jump_within.count);
    // The raw clips jump at their starts; blended, a start moves no more than a frame within a clip
    // (issue 30's target: p99 at starts <= 1.2 x p99 within).
    EXPECT_GT(before.jump_start.p99, 2.0 * before.jump_within.p99);
    EXPECT_LE(after.jump_start.p99, 1.2 * after.jump_within.p99)
        << after.jump_start.p99 << " vs " << after.jump_within.p99;
    EXPECT_LE(after.jump_start.median, after.jump_start.p99);
}

TEST(MotionMetrics, SpreadIsTheMedianAndTheP99) {
    std::vector<double> v;
    for (int i = 100; i >= 1; --i) v.push_back(i);
    const Spread s = spread_of(v);
    EXPECT_EQ(s.count, 100u);
    EXPECT_EQ(s.median, 50);
    EXPECT_EQ(s.p99, 99);
    std::vector<double> none;
    EXPECT_EQ(spread_of(none).p99, 0);
}

// Walking clips plant their feet: a toe is in contact for part of each stride and then barely moves;
// the record's metrics carry both kinds of poses.
TEST(MotionMetrics, WalkingFeetArePlantedInContact) {
    MOBB_REQUIRE_MOCAP();
    std::vector<int> agents;
    for (int a = 0; a < int(record().tracks.size()); ++a) agents.push_back(a);
    CrowdPoser p = poser();
    const CrowdMotion m = motion_metrics(p, agents, 0, record().frames, 2);
    ASSERT_TRUE(m.raw.feet);
    const FootSliding& walk = m.raw.sliding[std::size_t(ClipKind::Walk)];
    ASSERT_GT(walk.steps, 1000u);
    EXPECT_GT(double(walk.contact), 0.2 * double(walk.steps));
    EXPECT_LT(double(walk.contact), 0.8 * double(walk.steps));
    EXPECT_LT(walk.speed.median, 0.2);  // m/s: planted, where a walker's root moves at about 1 m/s
    EXPECT_LT(walk.skate_share, 0.3);
    EXPECT_GT(walk.speed.p99, FootContact::kSkateSpeed);  // a toe passing low in swing counts too (GMD's rule)
    const auto j = nlohmann::json::parse(with_motion("{\"passed\": true}", m));
    EXPECT_TRUE(j["passed"].get<bool>());
    EXPECT_EQ(j["motion"]["joints"].get<int>(), p.rig().size());
    EXPECT_EQ(j["motion"]["raw"]["jump_start"]["count"].get<std::size_t>(), m.raw.jump_start.count);
    EXPECT_TRUE(j["motion"]["blended"]["foot_sliding"].contains("walk"));
}

// The heel runs of a foot planted across a clip start, frames [k0, k1] (feet found in the mocap), of every
// agent of the test record.
struct HeelRun {
    int agent = 0, foot = 0;
    std::int64_t k0 = 0, k1 = 0;
};
std::vector<HeelRun> heel_runs_across_starts(CrowdPoser& p) {
    std::vector<glm::dvec3> pose, raw, unlocked;
    FeetAt feet;
    std::vector<HeelRun> out;
    for (int a = 0; a < int(record().tracks.size()); ++a)
        for (std::size_t c = 1; c < record().tracks[std::size_t(a)].clips.size(); ++c) {
            const std::int64_t start = record().tracks[std::size_t(a)].clips[c].start;
            for (int f = 0; f < 2; ++f) {
                const auto heel = [&](std::int64_t k) {
                    return p.pose(a, k, pose, raw, unlocked, &feet) && feet.plant[std::size_t(f)] == Plant::Heel;
                };
                if (!heel(start - 1) || !heel(start)) continue;
                HeelRun r{a, f, start - 1, start};
                while (heel(r.k0 - 1)) --r.k0;
                while (heel(r.k1 + 1)) ++r.k1;
                out.push_back(r);
            }
        }
    return out;
}

// A foot planted across a clip start stays where its heel came down, in the world, through the transition,
// where the blended clips alone move it: each frame it moves at most FootLock::glide's step on the ground
// and glide_height's in height, plus what the hold says it was lifted or dragged (the leg could not reach,
// or the disk); most holds are never lifted nor dragged.
TEST(FootLock, APlantedFootStaysPutAcrossAClipStart) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser locked = poser(), free = poser({}, RigJoints::All, false);
    const double glide = FootLock{}.glide * record().dt, rise = FootLock{}.glide_height * record().dt;
    std::vector<glm::dvec3> pose, raw, unlocked, free_pose;
    FeetAt feet;
    int held = 0, undragged = 0;
    double free_moved = 0;
    for (const HeelRun& r : heel_runs_across_starts(locked)) {
        const std::size_t f = std::size_t(r.foot), ankle = std::size_t(locked.legs()[f].ankle);
        ASSERT_TRUE(locked.pose(r.agent, r.k0, pose, raw, unlocked, &feet));
        glm::dvec3 last = pose[ankle];
        const glm::dvec3 free_first = unlocked[ankle];
        double slack = feet.residual[f];
        bool exact = true;
        for (std::int64_t k = r.k0 + 1; k <= r.k1; ++k) {
            ASSERT_TRUE(locked.pose(r.agent, k, pose, raw, unlocked, &feet) && free.pose(r.agent, k, free_pose));
            EXPECT_TRUE(feet.held[f]);
            slack += feet.residual[f] + feet.dragged[f];
            const glm::dvec3 moved = pose[ankle] - last;
            EXPECT_LE(std::hypot(moved.x, moved.y), slack + glide + 1e-9) << "agent " << r.agent << " frame " << k;
            EXPECT_LE(std::abs(moved.z), slack + rise + 1e-9) << "agent " << r.agent << " frame " << k;
            slack = feet.residual[f];
            last = pose[ankle];
            exact = exact && feet.residual[f] < 1e-9 && feet.dragged[f] == 0;
            // The free poser gives the unlocked pose.
            EXPECT_LT(glm::length(free_pose[ankle] - unlocked[ankle]), 1e-12);
            free_moved =
                std::max(free_moved, std::hypot(unlocked[ankle].x - free_first.x, unlocked[ankle].y - free_first.y));
        }
        ++held;
        undragged += exact;
    }
    EXPECT_GT(held, 20);
    EXPECT_GT(undragged, held / 2);  // most holds never run out of leg or disk
    EXPECT_GT(free_moved, 0.02);     // metres: without the lock the ankle slides through the transition
}

// Held still (no glide) a foot stays exactly where it came down; gliding, it ends its contact nearer where
// the clip played then has it than held still.
TEST(FootLock, AHeldFootGlidesToTheClipsOwnFootprint) {
    MOBB_REQUIRE_MOCAP();
    FootLock hold;
    hold.glide = hold.glide_height = 0;
    CrowdPoser still = poser({}, RigJoints::All, true, true, hold), glides = poser();
    std::vector<glm::dvec3> pose, raw, unlocked;
    FeetAt feet;
    double off_still = 0, off_glide = 0;
    int runs = 0, exact = 0;
    for (const HeelRun& r : heel_runs_across_starts(still)) {
        const std::size_t ankle = std::size_t(still.legs()[std::size_t(r.foot)].ankle);
        ASSERT_TRUE(still.pose(r.agent, r.k0, pose, raw, unlocked, &feet));
        const glm::dvec3 first = pose[ankle];
        ASSERT_TRUE(still.pose(r.agent, r.k1, pose, raw, unlocked, &feet));
        exact += feet.dragged[std::size_t(r.foot)] == 0 && glm::length(pose[ankle] - first) < 1e-9;
        off_still += glm::length(pose[ankle] - raw[ankle]);
        ASSERT_TRUE(glides.pose(r.agent, r.k1, pose, raw, unlocked, &feet));
        off_glide += glm::length(pose[ankle] - raw[ankle]);
        ++runs;
    }
    EXPECT_GT(runs, 20);
    EXPECT_GT(exact, runs / 2);
    EXPECT_LT(off_glide, off_still);
}

// Out of the leg's reach a held foot is lifted before it is dragged (FootLock::lift): over the heels planted
// across clip starts it moves less on the ground than when it is dragged towards the hip at once.
TEST(FootLock, AFootOutOfReachIsLiftedBeforeItIsDragged) {
    MOBB_REQUIRE_MOCAP();
    FootLock drag;
    drag.lift = false;
    CrowdPoser lifts = poser(), drags = poser({}, RigJoints::All, true, true, drag);
    std::vector<glm::dvec3> pose, raw, unlocked;
    const auto ground_moves = [&](CrowdPoser& p, const std::vector<HeelRun>& runs) {
        double sum = 0;
        for (const HeelRun& r : runs) {
            const std::size_t ankle = std::size_t(p.legs()[std::size_t(r.foot)].ankle);
            glm::dvec3 last{0.0};
            for (std::int64_t k = r.k0; k <= r.k1; ++k) {
                EXPECT_TRUE(p.pose(r.agent, k, pose));
                if (k > r.k0) sum += std::hypot(pose[ankle].x - last.x, pose[ankle].y - last.y);
                last = pose[ankle];
            }
        }
        return sum;
    };
    const std::vector<HeelRun> runs = heel_runs_across_starts(lifts);
    ASSERT_GT(runs.size(), 20U);
    EXPECT_LT(ground_moves(lifts, runs), ground_moves(drags, runs));
}

// Where a clip ends with a foot planted and the next one has it up from its start, the blend eases out of
// the planted pose and carries the foot off while it is still low; the lock holds it (FootLock::carry)
// through the blend, as planted as it was at the clip's last frame, moving only where the hold says it
// was lifted or dragged, and most never on the ground. Without carry those frames are not held.
TEST(FootLock, AFootPlantedAtAClipsEndIsHeldThroughTheBlend) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser locked = poser(), uncarried = poser({}, RigJoints::All, true, false);
    std::vector<glm::dvec3> pose, raw, unlocked, other;
    FeetAt feet, other_feet;
    int carried = 0, still = 0;
    double free_moved = 0;
    for (int a = 0; a < int(record().tracks.size()); ++a)
        for (std::size_t c = 1; c < record().tracks[std::size_t(a)].clips.size(); ++c) {
            const std::int64_t start = record().tracks[std::size_t(a)].clips[c].start;
            for (std::size_t f = 0; f < 2; ++f) {
                if (!locked.pose(a, start - 1, pose, raw, unlocked, &feet) || feet.plant[f] == Plant::Free) continue;
                const Plant plant = feet.plant[f];
                const std::size_t j = std::size_t(plant == Plant::Toe ? locked.legs()[f].toe : locked.legs()[f].ankle);
                glm::dvec3 last = pose[j];
                const glm::dvec3 free_first = unlocked[j];
                bool moved = false;
                std::int64_t k = start;
                for (; locked.pose(a, k, pose, raw, unlocked, &feet) && feet.plant[f] == Plant::Free &&
                       feet.hold[f] != Plant::Free;
                     ++k) {
                    EXPECT_EQ(feet.hold[f], plant) << "agent " << a << " frame " << k;
                    EXPECT_TRUE(feet.held[f]);
                    EXPECT_LE(glm::length(pose[j] - last), feet.dragged[f] + feet.residual[f] + 1e-9)
                        << "agent " << a << " frame " << k;
                    moved = moved || std::hypot(pose[j].x - last.x, pose[j].y - last.y) > 1e-9;
                    last = pose[j];
                    free_moved =
                        std::max(free_moved, std::hypot(unlocked[j].x - free_first.x, unlocked[j].y - free_first.y));
                    ASSERT_TRUE(uncarried.pose(a, k, other, raw, unlocked, &other_feet));
                    EXPECT_EQ(other_feet.hold[f], Plant::Free);
                }
                if (k == start) continue;
                ++carried;
                still += !moved;
            }
        }
    EXPECT_GT(carried, 5);
    EXPECT_GT(still, carried / 2);  // most carried feet do not move on the ground (they may rise: FootLock::lift)
    EXPECT_GT(free_moved, 0.02);    // metres: the blend alone carries them off
}

// What the poses of the test crowd do with the toe in frame steps where the free pose keeps it below GMD's
// contact height, by what held the foot at the step's end: the world distance it moved in all, and the steps.
struct LowSteps {
    double moved = 0;
    int steps = 0;
};
template <class Which>
LowSteps low_steps(FootLock lock, Which which) {
    CrowdPoser p(record(), std::make_shared<PoseSources>(graph()), RigJoints::All, {}, lock);
    std::vector<glm::dvec3> pose, raw, unlocked;
    FeetAt feet, before;
    LowSteps out;
    for (int a = 0; a < int(record().tracks.size()); ++a)
        for (std::size_t f = 0; f < 2; ++f) {
            const std::size_t toe = std::size_t(p.legs()[f].toe);
            bool have = false;
            glm::dvec3 last{0.0};
            double last_height = 0;
            for (std::int64_t k = 0; k < record().frames; ++k) {
                if (!p.pose(a, k, pose, raw, unlocked, &feet)) {
                    have = false;
                    continue;
                }
                if (have && last_height < FootLock{}.toe_down && unlocked[toe].z < FootLock{}.toe_down &&
                    which(before, feet, f)) {
                    out.moved += std::hypot(pose[toe].x - last.x, pose[toe].y - last.y);
                    ++out.steps;
                }
                have = true;
                last = pose[toe];
                last_height = unlocked[toe].z;
                before = feet;
            }
        }
    return out;
}

// After a contact the lock lets go over FootLock::release. In the world (release_in_world) the toe goes
// from where it was held to where the free pose has it, so a foot the pose moves over the floor stays
// behind: on the test crowd, with pins off, its toe moves 21.7 m over the floor in 1,244 steps while let go,
// against 28.2 m when the correction decays against the pose.
TEST(FootLock, ALetGoFootStaysBehindInTheWorld) {
    MOBB_REQUIRE_MOCAP();
    const auto letting_go = [](const FeetAt&, const FeetAt& now, std::size_t f) {
        return now.held[f] && now.hold[f] == Plant::Free && !now.pinned[f];
    };
    FootLock world, against_pose;
    world.pin = against_pose.pin = false;
    against_pose.release_in_world = false;
    const LowSteps in_world = low_steps(world, letting_go), decaying = low_steps(against_pose, letting_go);
    EXPECT_GT(in_world.steps, 200);
    EXPECT_EQ(in_world.steps, decaying.steps);  // the same releases: where the toe is low is the free pose's
    EXPECT_LT(in_world.moved, 0.85 * decaying.moved)
        << in_world.moved << " m against " << decaying.moved << " m over " << in_world.steps << " steps";
}

// One frame of an agent as the tests below read it.
struct Posed {
    std::vector<glm::dvec3> pose, raw, unlocked;
    FeetAt feet;
};

// step(agent, k, foot, before, now) for each foot at each frame step k - 1 -> k of the test crowd's agents.
template <class Step>
void each_step(CrowdPoser& p, Step step) {
    Posed now, before;
    for (int a = 0; a < int(record().tracks.size()); ++a)
        for (std::int64_t k = 0; k < record().frames; ++k) {
            if (!p.pose(a, k, now.pose, now.raw, now.unlocked, &now.feet)) continue;
            for (std::size_t f = 0; f < 2 && k > 0; ++f) step(a, k, f, before, now);
            std::swap(before, now);
        }
}

double ground_step(const glm::dvec3& from, const glm::dvec3& to) { return std::hypot(to.x - from.x, to.y - from.y); }

// Metres a held foot may move off its target over a step: dragged at the step's end, or short of the target
// at either end.
double leeway(const Posed& before, const Posed& now, std::size_t f) {
    return now.feet.dragged[f] + now.feet.residual[f] + before.feet.residual[f] + 1e-9;
}

// In the blend after a clip start a foot in no contact whose toe is down, and which the clip itself moves
// slowly, is pinned (FootLock::pin): from one pinned frame to the next its toe stays put on the floor (unless
// the leg cannot reach it), where the free pose moves it (1.23 m over the test crowd's 51 such steps); over
// all steps with the toe down, the toes move 83.9 m against 84.5 m with pins off.
TEST(FootLock, AFootLowInABlendIsPinned) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser p = poser();
    int pinned = 0;
    double free_moved = 0;
    each_step(p, [&](int a, std::int64_t k, std::size_t f, const Posed& before, const Posed& now) {
        if (!now.feet.pinned[f] || !before.feet.pinned[f]) return;
        const std::size_t toe = std::size_t(p.legs()[f].toe);
        ++pinned;
        EXPECT_LE(ground_step(before.pose[toe], now.pose[toe]), leeway(before, now, f))
            << "agent " << a << " frame " << k;
        free_moved += ground_step(before.unlocked[toe], now.unlocked[toe]);
    });
    EXPECT_GT(pinned, 20);
    EXPECT_GT(free_moved, 0.01 * pinned);  // metres: the blend alone moves them 1 cm a frame on average
    FootLock off;
    off.pin = false;
    const auto blended_low = [](const FeetAt&, const FeetAt&, std::size_t) { return true; };
    EXPECT_LT(low_steps(FootLock{}, blended_low).moved, low_steps(off, blended_low).moved);
}

// The fastest the clip itself moves a pinned toe (the raw clip's step, within one clip) in walk clips or in the
// others, over the test crowd, and how many frames of those are pinned.
double fastest_pinned(FootLock lock, bool walks, int& pinned) {
    CrowdPoser p(record(), std::make_shared<PoseSources>(graph()), RigJoints::All, {}, lock);
    double fastest = 0;
    pinned = 0;
    each_step(p, [&](int a, std::int64_t k, std::size_t f, const Posed& before, const Posed& now) {
        AgentClipAt at;
        // Frame k - 1 must be the same clip's for the raw step to be the clip's own.
        if (!now.feet.pinned[f] || !agent_clip_at(record(), *graph(), a, k, at) || k == at.placed->start) return;
        const int clip = at.placed->clip;
        if ((kind_of(graph()->clips[std::size_t(clip)], clip) == ClipKind::Walk) != walks) return;
        const std::size_t toe = std::size_t(p.legs()[f].toe);
        ++pinned;
        fastest = std::max(fastest, ground_step(before.raw[toe], now.raw[toe]) / record().dt);
    });
    return fastest;
}

// In a walk a pin holds a foot the blend moves, not one the clip itself moves faster than FootLock::pin_speed
// (a swing or a slide as captured); in the other clips (FootLock::pin_shuffles) a low foot is pinned at any
// speed. Pinned at any speed in walks too, the test crowd has more walking toes pinned, some of which the clip
// moves at over twice that speed; without pin_shuffles no toe is pinned faster than pin_speed.
TEST(FootLock, AFootTheClipMovesIsPinnedOnlyOutsideWalks) {
    MOBB_REQUIRE_MOCAP();
    const double limit = FootLock{}.pin_speed;
    int walking = 0, any_speed_walking = 0, shuffling = 0, not_shuffling = 0;
    FootLock any_speed, no_shuffles;
    any_speed.pin_speed = 1e9;
    no_shuffles.pin_shuffles = false;
    EXPECT_LE(fastest_pinned(FootLock{}, true, walking), limit + 1e-9);
    EXPECT_GT(fastest_pinned(any_speed, true, any_speed_walking), 2 * limit);
    EXPECT_GT(walking, 20);
    EXPECT_GT(any_speed_walking, walking);
    EXPECT_GT(fastest_pinned(FootLock{}, false, shuffling), 2 * limit);
    EXPECT_LE(fastest_pinned(no_shuffles, false, not_shuffling), limit + 1e-9);
    EXPECT_GT(shuffling, not_shuffling);
}

// A contact that begins while a pin or a release still holds the foot comes down where that left it: at its
// first frame the ankle moves as the free pose's does (a leg out of reach aside), where it jumped to the
// free pose's place before (136 such starts on the test crowd, the foot held up to 6 cm off the free pose).
TEST(FootLock, AContactComesDownWhereTheFootIs) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser p = poser();
    int starts = 0;
    double largest = 0;
    each_step(p, [&](int a, std::int64_t k, std::size_t f, const Posed& before, const Posed& now) {
        if (now.feet.hold[f] == Plant::Free || before.feet.hold[f] != Plant::Free || !before.feet.held[f]) return;
        const std::size_t ankle = std::size_t(p.legs()[f].ankle);
        const glm::dvec3 step = (now.pose[ankle] - before.pose[ankle]) - (now.unlocked[ankle] - before.unlocked[ankle]);
        ++starts;
        EXPECT_LE(std::hypot(step.x, step.y), leeway(before, now, f)) << "agent " << a << " frame " << k;
        largest = std::max(largest, ground_step(before.unlocked[ankle], before.pose[ankle]));
    });
    EXPECT_GT(starts, 20);
    EXPECT_GT(largest, 0.03);  // metres the foot was held off the free pose where some contact began
}

// A hold is followed frame by frame and kept per agent and foot; posing the frames backwards (every frame
// starting its hold over) gives the same poses as posing them in order, to the bit.
TEST(FootLock, PosesDoNotDependOnTheOrderFramesArePosedIn) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser forward = poser(), backward = poser();
    std::vector<glm::dvec3> a, b;
    const std::int64_t frames = std::min<std::int64_t>(record().frames, 300);
    std::vector<std::vector<glm::dvec3>> ahead;
    for (int agent = 0; agent < int(record().tracks.size()); ++agent) {
        ahead.clear();
        for (std::int64_t k = 0; k < frames; ++k) {
            ASSERT_TRUE(forward.pose(agent, k, a));
            ahead.push_back(a);
        }
        for (std::int64_t k = frames - 1; k >= 0; --k) {
            ASSERT_TRUE(backward.pose(agent, k, b));
            for (std::size_t j = 0; j < b.size(); ++j)
                ASSERT_EQ(b[j], ahead[std::size_t(k)][j]) << "agent " << agent << " frame " << k << " joint " << j;
        }
    }
}

TEST(AgentPose, TimesBetweenFramesInterpolate) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser p = poser();
    std::vector<glm::dvec3> a, b, mid, at;
    ASSERT_TRUE(p.pose(3, 40, a) && p.pose(3, 41, b) && p.pose_at(3, 40.5 * record().dt, mid));
    ASSERT_TRUE(p.pose_at(3, 40 * record().dt, at));
    for (std::size_t j = 0; j < a.size(); ++j) {
        EXPECT_LT(glm::length(mid[j] - 0.5 * (a[j] + b[j])), 1e-9);
        EXPECT_LT(glm::length(at[j] - a[j]), 1e-9);
    }
}

// The world positions of skin K's joints at frame f, from the file's node tree and animation alone.
std::vector<glm::dvec3> gltf_joints(const tinygltf::Model& m, int skin, int frame) {
    const tinygltf::Animation& anim = m.animations.at(0);
    std::vector<glm::dvec3> local(m.nodes.size());
    for (std::size_t n = 0; n < m.nodes.size(); ++n)
        if (m.nodes[n].translation.size() == 3)
            local[n] = {m.nodes[n].translation[0], m.nodes[n].translation[1], m.nodes[n].translation[2]};
    for (const tinygltf::AnimationChannel& c : anim.channels) {
        const tinygltf::Accessor& acc = m.accessors[std::size_t(anim.samplers[std::size_t(c.sampler)].output)];
        const tinygltf::BufferView& v = m.bufferViews[std::size_t(acc.bufferView)];
        const auto* f = reinterpret_cast<const float*>(m.buffers[0].data.data() + v.byteOffset + acc.byteOffset) +
                        3 * std::size_t(frame);
        local[std::size_t(c.target_node)] = {f[0], f[1], f[2]};
    }
    std::vector<int> parent(m.nodes.size(), -1);
    for (std::size_t n = 0; n < m.nodes.size(); ++n)
        for (int c : m.nodes[n].children) parent[std::size_t(c)] = int(n);
    std::vector<glm::dvec3> out;
    for (int node : m.skins.at(std::size_t(skin)).joints) {
        glm::dvec3 w(0.0);
        for (int n = node; n >= 0; n = parent[std::size_t(n)]) w += local[std::size_t(n)];
        out.push_back(w);
    }
    return out;
}

TEST(ExportCrowd, GltfHoldsOneSkinPerAgentOnItsTrack) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser p = poser();
    CrowdExportOptions o;
    o.agent_begin = 2;
    o.agent_end = 7;
    o.t_begin = 3;
    o.t_end = 13;
    o.bodies = true;
    const io::ExportScene scene = crowd_scene(p, o);
    EXPECT_EQ(scene.frames, 301);
    const std::string file = test::temp_file("crowd.glb");
    const auto bytes = io::write_gltf(scene, file);
    EXPECT_EQ(bytes, std::filesystem::file_size(file));
    EXPECT_FALSE(std::filesystem::exists(file + ".part"));

    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, file)) << err;
    std::remove(file.c_str());
    ASSERT_EQ(m.skins.size(), 5u);
    ASSERT_EQ(m.animations.size(), 1u);
    int bodies = 0;
    for (const tinygltf::Node& n : m.nodes) bodies += n.skin >= 0 && n.mesh >= 0;
    EXPECT_EQ(bodies, 5);
    const tinygltf::Accessor& times = m.accessors[std::size_t(m.animations[0].samplers[0].input)];
    EXPECT_EQ(times.count, 301u);
    EXPECT_NEAR(times.minValues[0], 3.0, 1e-6);
    EXPECT_NEAR(times.maxValues[0], 13.0, 1e-5);
    double root_error = 0, joint_error = 0, lock_moved = 0;
    std::vector<glm::dvec3> pose, raw, unlocked;
    for (int k = 0; k < 5; ++k) {
        const int agent = 2 + k;
        EXPECT_EQ(m.nodes[std::size_t(m.skins[std::size_t(k)].joints[0])].name,
                  "agent " + std::to_string(agent) + " " + p.rig().names[0]);
        for (int f = 0; f < scene.frames; ++f) {
            const std::int64_t frame = 90 + f;  // 3 s at 30 fps
            const auto joints = gltf_joints(m, k, f);
            const glm::dvec2 root = root_of_agent(record(), *graph(), agent, frame);
            // glTF is Y up: the ground point (x, y) is (x, -z).
            root_error = std::max(root_error, std::hypot(joints[0].x - root.x, -joints[0].z - root.y));
            ASSERT_TRUE(p.pose(agent, frame, pose, raw, unlocked, nullptr));
            for (std::size_t j = 0; j < pose.size(); ++j) {
                joint_error =
                    std::max(joint_error, glm::length(joints[j] - glm::dvec3(pose[j].x, pose[j].z, -pose[j].y)));
                lock_moved = std::max(lock_moved, glm::length(pose[j] - unlocked[j]));
            }
        }
    }
    EXPECT_LT(root_error, 1e-3);
    EXPECT_LT(joint_error, 1e-3);
    EXPECT_GT(lock_moved, 0.01);  // metres: the file has the locked feet, not the free ones
}

TEST(ExportCrowd, BvhComesBackAsTheAgentsTrack) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser p = poser();
    CrowdExportOptions o;
    o.agent_begin = 4;
    o.agent_end = 6;
    const io::ExportScene scene = crowd_scene(p, o);
    const std::string file = test::temp_file("agent.bvh");
    io::write_bvh(scene, 1, file);
    const io::Clip clip = io::load_clip(file);
    std::remove(file.c_str());
    EXPECT_EQ(clip.scale, 1.0) << clip.scale_reason;
    ASSERT_EQ(std::int64_t(clip.path.size()), record().frames);
    EXPECT_NEAR(clip.animation.dt, record().dt, 1e-9);
    double error = 0;
    for (std::size_t k = 0; k < clip.path.size(); ++k) {
        const glm::dvec2 root = root_of_agent(record(), *graph(), 5, std::int64_t(k));
        error = std::max(error, std::hypot(clip.path.samples[k].x - root.x, clip.path.samples[k].y - root.y));
    }
    EXPECT_LT(error, 1e-3);
}

TEST(ExportCrowd, BadRangesAndFilesAreRefused) {
    MOBB_REQUIRE_MOCAP();
    CrowdPoser p = poser({}, RigJoints::Major);
    EXPECT_LT(p.rig().size(), 30);
    const auto refused = [&](CrowdExportOptions o, const std::string& what) {
        try {
            crowd_scene(p, o);
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()).rfind(what, 0), 0u) << e.what();
            return;
        }
        ADD_FAILURE() << "accepted " << what;
    };
    CrowdExportOptions o;
    o.agent_begin = 3, o.agent_end = 3;
    refused(o, "--agents");
    o = {}, o.agent_end = 13;
    refused(o, "--agents");
    o = {}, o.agent_begin = -1;
    refused(o, "--agents");
    o = {}, o.t_begin = 5, o.t_end = 4;
    refused(o, "--time");
    o = {}, o.t_end = 31;
    refused(o, "--time");
    o = {}, o.fps = 5000;
    refused(o, "--fps");
    o = {}, o.agent_end = 1, o.t_end = 1;
    const io::ExportScene scene = crowd_scene(p, o);
    const std::string missing = test::temp_file("no/such/folder/crowd.glb");
    EXPECT_THROW(io::write_gltf(scene, missing), io::ExportError);
    EXPECT_FALSE(std::filesystem::exists(missing + ".part"));
    EXPECT_THROW(io::write_gltf(scene, test::temp_file("crowd.obj")), io::ExportError);
    EXPECT_THROW(io::write_bvh(scene, 1, test::temp_file("agent.bvh")), io::ExportError);
}

}  // namespace
}  // namespace mobb::crowd
