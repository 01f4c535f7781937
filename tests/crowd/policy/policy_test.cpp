// The selection policies on the committed graph: the order each puts a choice point's candidates in,
// and when a goal agent stops.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mobb/core/angle.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/policy/policy.h"
#include "plan/escape.h"
#include "policy/walls_ahead.h"

namespace mobb::crowd {
namespace {

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

struct Fixture {
    MotionGraph graph = load_graph(kGraph);
    std::vector<ClipKind> kinds;
    std::vector<char> in_place;
    std::vector<int> all;  // every clip, as the candidates of a choice point
    Fixture() {
        for (int k = 0; k < int(graph.clips.size()); ++k) {
            kinds.push_back(kind_of(graph.clips[std::size_t(k)], k));
            in_place.push_back(kinds.back() == ClipKind::InPlace || kinds.back() == ClipKind::Idle);
            all.push_back(k);
        }
    }
};

const Fixture& fixture() {
    static const Fixture f;
    return f;
}

std::vector<int> ordered(const Policy& p, const ChoiceSite& site) {
    std::vector<int> c = fixture().all;
    p.order(site, c);
    EXPECT_TRUE(std::is_permutation(c.begin(), c.end(), fixture().all.begin())) << "order() only reorders";
    return c;
}

Placement end_of(const ChoiceSite& site, int clip) { return fixture().graph.next(site.base, clip); }

TEST(Policy, RandomKeepsTheStreamOrder) {
    World w;
    const Fixture& f = fixture();
    const auto p = make_policy(Selection::Random, {f.graph, w, f.in_place, {}, 1.0, {}});
    std::vector<int> c = {5, 2, 9, 1};
    p->order({0, {10, 10, 0, 0}, std::nullopt, false, 0, false, std::nullopt, {}}, c);
    EXPECT_EQ(c, (std::vector<int>{5, 2, 9, 1}));
    EXPECT_EQ(p->kind(), Selection::Random);
}

TEST(Policy, AvoidWalksFirstAndTurnsAwayFromWalls) {
    World w;  // [0, 30] x [0, 40]
    const Fixture& f = fixture();
    const auto p = make_policy(Selection::Wander, {f.graph, w, f.in_place, {}, 1.0, {}});
    // In the open: every walking clip before every slow one that moves (at the idle speed or faster),
    // before every clip in place, before the slow ones that only creep.
    const ChoiceSite open{0, {15, 20, 0.3, 0}, std::nullopt, false, 0, false, std::nullopt, {}};
    auto rank = [&](int c) {
        const ClipKind k = f.kinds[std::size_t(c)];
        const GraphClip& g = f.graph.clips[std::size_t(c)];
        const double speed = std::hypot(g.exit_x, g.exit_y) / (double(g.path.size()) * f.graph.dt());
        if (k == ClipKind::Slow) return speed >= CrowdMetrics::kIdleSpeed ? 1 : 3;
        return k == ClipKind::Walk ? 0 : 2;
    };
    const std::vector<int> c = ordered(*p, open);
    for (std::size_t k = 1; k < c.size(); ++k) EXPECT_LE(rank(c[k - 1]), rank(c[k])) << "position " << k;
    // Stable within a rank: the stream's random order is kept.
    std::vector<int> walks;
    for (int x : f.all)
        if (rank(x) == 0) walks.push_back(x);
    EXPECT_TRUE(std::equal(walks.begin(), walks.end(), c.begin()));
    // Facing the wall 2 m ahead: the first clips walk back into the open, away from it.
    const ChoiceSite wall{0, {28, 20, 0, 0}, std::nullopt, false, 0, false, std::nullopt, {}};
    const std::vector<int> d = ordered(*p, wall);
    const Placement first = end_of(wall, d.front());
    EXPECT_LT(std::cos(first.theta), std::cos(end_of(wall, walks.front()).theta) + 1e-12);
    int toward = 0;
    for (int x : f.all)
        if (rank(x) == 0 && std::abs(std::remainder(end_of(wall, x).theta, 2 * 3.14159265358979)) < 0.2) ++toward;
    ASSERT_GT(toward, 0);
    for (std::size_t k = 0; k < d.size() && rank(d[k]) == 0; ++k) {
        const Placement e = end_of(wall, d[k]);
        const bool into_wall = std::cos(e.theta) > 0.99;
        if (into_wall) {
            // Walks into the wall come after those that do not.
            for (std::size_t j = k + 1; j < d.size() && rank(d[j]) == 0; ++j)
                EXPECT_GT(std::cos(end_of(wall, d[j]).theta), 0.0);
            break;
        }
    }
}

// Mean ground speed of a clip from its start to its exit (m/s).
double exit_speed(int clip) {
    const GraphClip& c = fixture().graph.clips[std::size_t(clip)];
    return std::hypot(c.exit_x, c.exit_y) / (double(c.path.size()) * fixture().graph.dt());
}

TEST(Policy, AvoidSlowsDownAsLittleAsItCanAndTurnsToTheOpen) {
    World w;  // [0, 30] x [0, 40]
    const Fixture& f = fixture();
    const auto p = make_policy(Selection::Wander, {f.graph, w, f.in_place, {}, 1.0, {}});
    // In the open: the slow clips the faster first.
    const std::vector<int> c = ordered(*p, {0, {15, 20, 0.3, 0}, std::nullopt, false, 0, false, std::nullopt, {}});
    std::vector<double> slow;
    for (int x : c)
        if (f.kinds[std::size_t(x)] == ClipKind::Slow) slow.push_back(exit_speed(x));
    ASSERT_GT(slow.size(), 2u);
    EXPECT_TRUE(std::is_sorted(slow.rbegin(), slow.rend()));
    // Facing the wall 2 m ahead: clips in place that end facing away from it before those facing it.
    const ChoiceSite wall{0, {28, 20, 0, 0}, std::nullopt, false, 0, false, std::nullopt, {}};
    bool faced_wall = false, turned_after = false, turned = false;
    for (int x : ordered(*p, wall)) {
        if (f.kinds[std::size_t(x)] != ClipKind::InPlace) continue;
        const double facing = std::cos(end_of(wall, x).theta);
        turned = turned || facing < -0.5;
        turned_after = turned_after || (faced_wall && facing < -0.5);
        faced_wall = faced_wall || facing > 0.9;
    }
    ASSERT_TRUE(turned && faced_wall) << "the graph turns on the spot both ways";
    EXPECT_FALSE(turned_after);
}

// Letting through (LetThroughTuning): before a door, the agent ranks first a clip that ends farther out of
// the lane of one coming through it the other way; one going its own way, or the rule off, leaves the
// order as it was.
TEST(Policy, GoalKeepsOutOfTheLaneOfOneComingThroughADoor) {
    World w{0, 0, 20, 12, true, {Polygon::rectangle(10, 0, 10.5, 5), Polygon::rectangle(10, 7, 10.5, 12)}};
    const Fixture& f = fixture();
    const std::array<double, 2> east{18, 6}, west{2, 6}, beyond{19, 6};
    CrowdTuning off;
    off.let_through.on = false;
    const auto on_p = make_policy(Selection::Goal, {f.graph, w, f.in_place, {east, west, beyond}, 1.0, {}});
    const auto off_p = make_policy(Selection::Goal, {f.graph, w, f.in_place, {east, west, beyond}, 1.0, off});
    ChoiceSite site{0, {8, 6, 0, 0}, east, true, 0, false, std::nullopt, {}};
    site.neighbours.push_back({{11.5, 6}, kPi, west, 1});  // at the door's far side, coming this way
    const std::vector<int> on = ordered(*on_p, site), off_order = ordered(*off_p, site);
    const auto aside = [&](int clip) { return std::abs(end_of(site, clip).y - 6); };
    // The lane: 1 m either side of y = 6 from x = 11.5 4 m west; the first clip without the rule ends in it.
    ASSERT_LT(aside(off_order.front()), 1.0);
    EXPECT_GT(aside(on.front()), aside(off_order.front()));
    // One going the same way through the door is no one to let through.
    site.neighbours.back().goal = beyond;
    EXPECT_EQ(ordered(*on_p, site), ordered(*off_p, site));
}

// Keeping right (KeepRightTuning): in a corridor, the agent meeting a stream coming the other way on its
// line ranks first a clip that ends farther right; one agent coming, or open ground, leaves the order as
// it was - but open ground in walls at an open cost.
TEST(Policy, GoalKeepsRightOfAStreamComingDownACorridor) {
    const Fixture& f = fixture();
    const std::array<double, 2> east{28, 0}, west{2, 0};
    CrowdTuning off;
    off.keep_right.on = false;
    const auto ordered_in = [&](const World& w, const ChoiceSite& site, const CrowdTuning& t) {
        return ordered(*make_policy(Selection::Goal, {f.graph, w, f.in_place, {east, west}, 1.0, t}), site);
    };
    const World corridor{0, -2.5, 30, 2.5, true, {}};
    ChoiceSite site{0, {10, 0, 0, 0}, east, true, 0, false, std::nullopt, {}};
    site.neighbours.push_back({{13, 0.2}, kPi, west, 1});
    const std::vector<int> one = ordered_in(corridor, site, {});
    EXPECT_EQ(one, ordered_in(corridor, site, off)) << "one agent coming is no stream";
    site.neighbours.push_back({{15, -0.3}, kPi, west, 2});
    const std::vector<int> on = ordered_in(corridor, site, {}), off_order = ordered_in(corridor, site, off);
    EXPECT_LT(end_of(site, on.front()).y, std::min(0.0, end_of(site, off_order.front()).y));
    const World open{0, -20, 30, 20, false, {}};
    EXPECT_EQ(ordered_in(open, site, {}), ordered_in(open, site, off)) << "open ground is no corridor";
    // Open ground in walls: kept right of at keep_right.open_cost, none with it 0.
    const World room{0, -20, 30, 20, true, {}};
    CrowdTuning in_the_open, not_in_the_open;
    not_in_the_open.keep_right.open_cost = 0;
    const std::vector<int> room_off = ordered_in(room, site, off);
    EXPECT_EQ(ordered_in(room, site, not_in_the_open), room_off);
    EXPECT_LT(end_of(site, ordered_in(room, site, in_the_open).front()).y,
              std::min(0.0, end_of(site, room_off.front()).y));
}

// Facing along walls (FaceAlongWallsTuning): an end beside a wall - nearer than room to turn - faces into
// it when the way ahead meets it; along it, away from it, or farther out, it does not.
TEST(Policy, WallsAheadAreThoseAnEndBesideThemFaces) {
    const EscapeTable e = EscapeTable::build(fixture().graph);
    const World w{-10, -10, 10, 10, false, {Polygon::rectangle(-0.5, -5, 0.5, 5)}};
    const WallsAhead walls(w, e.stand_clearance, e.turn_clearance, 0.25);
    const double beside = 0.5 + 0.5 * (e.stand_clearance + e.turn_clearance);
    EXPECT_TRUE(walls.facing_wall({beside, 0, kPi, 0}, 1.0)) << "into it";
    EXPECT_TRUE(walls.facing_wall({beside, 0, 0.75 * kPi, 0}, 1.0)) << "into it at a slant";
    EXPECT_FALSE(walls.facing_wall({beside, 0, kPi / 2, 0}, 1.0)) << "along it";
    EXPECT_FALSE(walls.facing_wall({beside, 0, 0, 0}, 1.0)) << "away from it";
    EXPECT_FALSE(walls.facing_wall({0.5 + e.turn_clearance + 0.3, 0, kPi, 0}, 1.0)) << "room to turn";
}

// At a wall beside a door, as evacuation_exit's agents reach it at a slant: with the rule, the first clip
// ends facing along the wall or away; without it, into the wall.
TEST(Policy, GoalFacesAlongAWallBesideADoor) {
    const Fixture& f = fixture();
    const EscapeTable e = EscapeTable::build(f.graph);
    const std::vector<Polygon> posts{Polygon::rectangle(-0.5, -10, 0.5, -1.2), Polygon::rectangle(-0.5, 1.2, 0.5, 10)};
    const World w{-16, -10, 20, 10, true, posts};
    const std::array<double, 2> goal{-10, 0};
    CrowdTuning off;
    off.face_along_walls.on = false;
    const auto make = [&](const CrowdTuning& t) {
        return make_policy(Selection::Goal,
                           {f.graph, w, f.in_place, {goal}, 1.0, t, e.stand_clearance, e.turn_clearance});
    };
    const WallsAhead walls(w, e.stand_clearance, e.turn_clearance, 0.25);
    const ChoiceSite site{0, {1.85, 4.95, -121 * kPi / 180, 0}, goal, true, 0, false, std::nullopt, {}};
    const std::vector<int> on = ordered(*make({}), site), off_order = ordered(*make(off), site);
    ASSERT_TRUE(walls.facing_wall(end_of(site, off_order.front()), 1.0));
    EXPECT_FALSE(walls.facing_wall(end_of(site, on.front()), 1.0));
}

TEST(Policy, GoalPrefersClipsTowardTheGoalAndStopsThere) {
    World w;
    w.x1 = 20;
    w.y1 = 20;
    const Fixture& f = fixture();
    const std::array<double, 2> goal{18, 10};
    const auto p = make_policy(Selection::Goal, {f.graph, w, f.in_place, {goal}, 1.0, {}});
    const ChoiceSite site{0, {5, 10, 0, 0}, goal, true, 0, false, std::nullopt, {}};
    const std::vector<int> c = ordered(*p, site);
    const double before = std::hypot(goal[0] - 5, goal[1] - 10);
    const Placement e = end_of(site, c.front());
    EXPECT_LT(std::hypot(goal[0] - e.x, goal[1] - e.y), before - 0.5);
    EXPECT_EQ(f.kinds[std::size_t(c.back())], ClipKind::Idle) << "standing comes last";
    // A neighbour where that clip ends moves it down the order.
    ChoiceSite crowded = site;
    crowded.neighbours.push_back({{e.x, e.y}, std::nullopt, std::nullopt, 1});
    const std::vector<int> d = ordered(*p, crowded);
    EXPECT_NE(d.front(), c.front());
    // Following (CrowdTuning::follow): the agent wants to go at its goal (down the navigation field, whose
    // eight-direction grid bends it by up to pi / 8); a neighbour there that faces the same way is one to
    // follow, not to keep away from - but one facing it is kept away from.
    const std::optional<double> way = p->heading(site);
    ASSERT_TRUE(way);
    EXPECT_LT(std::abs(*way), kPi / 8 + 1e-9);
    ChoiceSite following = site;
    following.way = way;
    following.neighbours.push_back({{e.x, e.y}, 0.1, std::nullopt, 1});
    EXPECT_EQ(ordered(*p, following), c);
    following.neighbours.back().facing = kPi;
    EXPECT_NE(ordered(*p, following).front(), c.front());
    // Arrived within the goal radius, not outside.
    EXPECT_TRUE(p->arrived({0, {17.3, 10.5, 0, 0}, goal, true, 0, false, std::nullopt, {}}));
    EXPECT_FALSE(p->arrived({0, {16.9, 10, 0, 0}, goal, true, 0, false, std::nullopt, {}}));
    EXPECT_FALSE(p->arrived({0, {17.3, 10.5, 0, 0}, std::nullopt, false, 0, false, std::nullopt, {}}));
}

// The goal straight ahead behind a wall: the first clips veer left, toward the way around it (its open
// end at y > 14), much more than with no wall, where they head straight on.
TEST(Policy, GoalFindsTheWayAroundAnObstacle) {
    World open;
    open.x1 = 20;
    open.y1 = 20;
    World walled = open;
    walled.obstacles.push_back(Polygon::rectangle(8, 0, 9, 14));
    const Fixture& f = fixture();
    const std::array<double, 2> goal{15, 10};
    const ChoiceSite site{0, {4, 10, 0, 0}, goal, true, 0, false, std::nullopt, {}};
    auto mean_turn = [&](const Policy& p) {
        const std::vector<int> c = ordered(p, site);
        double sum = 0;
        for (int k = 0; k < 4; ++k) sum += end_of(site, c[std::size_t(k)]).theta / 4;
        return sum;
    };
    const auto straight = make_policy(Selection::Goal, {f.graph, open, f.in_place, {goal}, 1.0, {}});
    const auto around = make_policy(Selection::Goal, {f.graph, walled, f.in_place, {goal}, 1.0, {}});
    EXPECT_LT(std::abs(mean_turn(*straight)), 0.15);
    EXPECT_GT(mean_turn(*around), 0.3);
    // Agents standing in the gap for good close it: the order changes.
    const auto blocked = make_policy(Selection::Goal, {f.graph, walled, f.in_place, {goal}, 1.0, {}});
    for (double y = 14.5; y < 20; y += 0.5) blocked->settled(8.5, y, 0.5);
    EXPECT_NE(ordered(*blocked, site), ordered(*around, site));
}

TEST(Policy, ParsesTheirNames) {
    for (Selection s : {Selection::Wander, Selection::Random, Selection::Goal})
        EXPECT_EQ(parse_selection(to_string(s)), s);
    EXPECT_THROW(parse_selection("nearest"), std::invalid_argument);
}

}  // namespace
}  // namespace mobb::crowd
