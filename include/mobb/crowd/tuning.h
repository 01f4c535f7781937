// Every number and switch that steers the crowd's agents, in one place (after Box2D's constants.h and
// DetourCrowd's dtCrowdAgentParams): per rule of the choice point a struct of its own - its switch `on`
// and its numbers, read by that rule alone (src/crowd/rules/, a header each) - then the escape's bounds
// and the policies' numbers. Each rule can be switched off on the command line - `mobb crowd
// --no-right-of-way`, `--no-give-way`, `--no-standing-gap`, `--no-look-ahead`, `--no-follow`,
// `--no-stand-near-walls`, `--no-leave-in-stride`, `--no-let-through`, `--no-keep-right`,
// `--no-face-along-walls` - and any field is set by name with `mobb crowd --tune NAME=VALUE` (set_tuning():
// `--tune give_way.reach=3`). What was measured to choose the values: bench/results/log.md, "Tuning: what
// was measured". Metrics keep their own thresholds (CrowdMetrics::kIdleSpeed): judging a run never changes
// how it runs.
#pragma once
#include <string>

namespace mobb::crowd {

/// The escape (src/crowd/plan/escape.h): the clips that stop an agent, then the ground it holds. Always
/// on - it is what keeps the crowd free of contacts - and bounded here.
struct EscapeTuning {
    int steps = 3;    ///< clips at most from a clip to a stop (longer chains: no route)
    int routes = 16;  ///< routes kept per clip, the shortest first (<= EscapeTable::kMaxRoutes)
    /// Metres beyond the clips' footprint that held ground and starts keep from walls and obstacles
    /// (EscapeTable::stand_clearance, turn_clearance): slack for rounding.
    double wall_margin = 0.1;
};

/// Stopping near walls (rules/stand_near_walls.h; goal agents only: Policy::stops_near_walls): held
/// ground keeps room to stand from walls and obstacles, not room to turn on the spot; a turn is tested
/// against the walls where it is chosen, as every clip is. Trades the certainty that a stopped agent can
/// turn round for ground to stop on in doors and corridors.
struct StandNearWallsTuning {
    bool on = true;
};

/// Leaving in stride (rules/leave_in_stride.h): a clip that ends within the goal radius of an agent's
/// exit (its last goal, AtGoal::Leave) is its whole plan - no stop reserved beyond the exit, where it
/// leaves the run. Off, the exit holds each leaver's stop until it has left, and those behind queue for it.
struct LeaveInStrideTuning {
    bool on = true;
};

/// The right of way (rules/right_of_way.h; Okumura et al.'s PIBT, 2019): an agent that has not moved for
/// `after` seconds may take a walk whose plan meets only the reservations of at most `max_rerouted`
/// agents walking a clip, each of which then stops another way. Trades a waiting agent's time against
/// the others' detours.
struct RightOfWayTuning {
    bool on = true;
    double after = 2.0;    ///< seconds without a moving clip
    int max_rerouted = 2;  ///< agents whose reservations one taking may move
};

/// Giving way (rules/give_way.h): a free walk passing within `reach` metres of an agent that has not
/// moved for `after` seconds is taken only when no later free walk keeps clear of such agents. Reorders,
/// never refuses: trades a walker's detour for the waiting agent's way out.
struct GiveWayTuning {
    bool on = true;
    double after = 2.0;  ///< seconds without a moving clip
    double reach = 2.5;  ///< metres from the walk's root to where the agent waits
};

/// Letting through (policy/passage.h; the goal policy): at a passage - free ground narrower than `narrow`
/// metres between solids, a door or a gap - an agent keeps out of the way of one coming through it the
/// other way that is nearer the passage than itself: within `reach` metres of a passage, an end of its
/// clips that lies in the lane ahead of such an agent (`lane_length` metres along that agent's way,
/// `lane_width` either side) costs up to `cost` seconds, the most on the lane's middle. Counter-flow at a
/// door then takes turns - who is nearer goes first - instead of both streams filling its mouths
/// (bench/results/log.md, "Letting through at doors"). Reorders, never refuses.
struct LetThroughTuning {
    bool on = true;
    double narrow = 3.0;       ///< metres: about two walking agents abreast with room between
    double reach = 4.0;        ///< metres from a passage
    double lane_length = 4.0;  ///< metres
    double lane_width = 1.0;   ///< metres either side: a walking disk and half a disk
    double cost = 3.0;         ///< seconds
    /// Radians (120 degrees) or more between the other's way and the agent's, both read where the other is
    /// (down each one's navigation field): coming the other way, for this rule and keeping right.
    double oncoming = 2.1;
};

/// Keeping right (the goal policy; Helbing and Molnar's bias to one side, 1995): where the free ground
/// across its way is narrower than `corridor` metres (a corridor, a door; PassageMap::across), an agent
/// with `stream` or more agents coming the other way (LetThroughTuning::oncoming) within `ahead` metres
/// ahead ranks its clips as if an end cost `cost` seconds per metre it lies left of the line `offset`
/// metres right of those within `offset` of its line. Both streams keep right and pass in lanes instead of
/// meeting across the whole width; one agent coming is left to the reservations (bench/results/log.md,
/// "Keeping right in corridors"). Elsewhere the same at `open_cost`. Reorders, never refuses.
struct KeepRightTuning {
    bool on = true;
    double corridor = 9.0;  ///< metres
    double ahead = 6.0;     ///< metres
    double offset = 1.2;    ///< metres: a walking disk's width and a little more
    double cost = 6.0;      ///< seconds per metre
    int stream = 2;         ///< oncoming agents ahead, at least: a stream, not one passer-by
    /// Seconds per metre the same where the ground across is `corridor` metres or wider (open ground in walls
    /// or among obstacles; 0: only in corridors and doors). Lower than in a corridor, where 3 lost what 6 won:
    /// circle_20 then runs as people's roundabout, under 1.5x the straight line on every seed, and SteerSuite's
    /// wide counter-flow hallways move (bench/results/log.md, "Keeping right in the open").
    double open_cost = 3.0;
};

/// Facing along walls (the goal policy; policy/walls_ahead.h): an end nearer a wall or an obstacle than
/// room to turn on the spot (EscapeTable::turn_clearance) that faces into it - the points half of `ahead`
/// and `ahead` metres along its heading nearer it than room to stand (EscapeTable::stand_clearance) - costs
/// `cost` seconds more. There an agent can neither walk on nor turn round: evacuation_exit's agents that
/// stopped at a slant into the wall beside its door stood there for half a minute (bench/results/log.md,
/// "Facing along walls"). Reorders, never refuses.
struct FaceAlongWallsTuning {
    bool on = true;
    double ahead = 1.0;  ///< metres: about the first step of a walk
    double cost = 2.0;   ///< seconds (>= 0)
};

/// The standing gap (rules/standing_gap.h): a policy that keeps it (wandering, not goal agents, which
/// converge on purpose) takes no escape route whose held ground comes within `width` metres, beyond the
/// disks, of another's. Trades where an agent may stop for room to pass between those who stopped, so
/// that stopped agents do not pack into knots that walkers cannot pass.
struct StandingGapTuning {
    bool on = true;
    double width = 0.45;  ///< metres
};

/// The look-ahead (rules/look_ahead.h; Lau and Kuffner 2005, Silver 2005): a goal agent searches clip
/// sequences GoalTuning::horizon clips deep, at most `budget` clips tested per choice point; a first clip
/// whose every sequence met a reservation ranks `dead_end` seconds behind. The budget bounds a choice
/// point's cost.
struct LookAheadTuning {
    bool on = true;
    int budget = 96;        ///< clips tested per choice point, at most
    double dead_end = 2.0;  ///< seconds
    /// How much more the time to go weighs in the order of search than in the score (weighted A*, Pohl
    /// 1970; 1: plain best-first): the search follows a sequence that gains ground to the horizon before
    /// widening.
    double weight = 2.0;
    /// Whether a place's estimate rises to what earlier searches found (LearnedCost; Korf's LRTA*): a
    /// place an agent waited in fills up until another way scores better. Off, the queues jostle less
    /// but stay longer.
    bool learns = true;
};

/// Following (rules/follow.h; Silver 2005: reservations trusted within a window): a goal agent follows
/// the agents ahead of it - within `angle` of its way (down its navigation field: NavField::downhill) -
/// that face its way, unless they end their clip within `goal_reach` of the goal they stop at: beyond
/// its first clip its look-ahead plans past their reservations (escape clips and held ground, never the
/// clip they play), and its estimate of the time to go counts no crowding for them. Its first clip and
/// that clip's escape are tested against everything, as always. Trades detours round a queue for waiting
/// in it: queues at doors and in corridors move sooner, crossings in the open later.
struct FollowTuning {
    bool on = true;
    double angle = 0.8;       ///< radians (46 degrees) either side of the agent's way
    double goal_reach = 3.0;  ///< metres: a leader this near its goal is about to stand there for good
};

/// The goal policy (src/crowd/policy/policy_goal.cpp). Its estimate of the time to go: path length at
/// `walking` m/s, plus the turn to face down the path at `turning` rad/s, plus `crowding` seconds per metre
/// an end comes nearer than `personal` to a neighbour - where the others' reservations will be, within
/// `neighbourhood` metres and `neighbours_ahead` seconds of the choice point.
struct GoalTuning {
    double walking = 1.3;   ///< m/s: the committed graph's walking clips, rounded
    double turning = 1.3;   ///< rad/s: its turning clips, rounded
    double personal = 2.0;  ///< metres
    /// Seconds per metre: trades following close (queues flow) against room where agents settle (late
    /// arrivals are not hemmed in short of their goals).
    double crowding = 1.2;
    int patience = 3;  ///< choice points without moving on before trying candidates at random, those that move first
    int horizon = 3;   ///< clips searched ahead (the look-ahead; about 3.6 s of the committed graph's clips)
    double nav_clearance = 0.45;  ///< metres the navigation fields keep from walls and obstacles
    /// Metres around the agent (Policy::neighbourhood): as far as a searched sequence's end reaches, plus
    /// `personal`.
    double neighbourhood = 6.0;
    double neighbours_ahead = 4.0;  ///< seconds from the choice point: about the searched horizon
};

/// Wandering (src/crowd/policy/policy_wander.cpp): walks whose end has `open_ahead` metres of ground ahead
/// before the world's edge come first, those with less in bands `band` metres wide, the less room the
/// later: a bias toward the open that turns agents from the walls a few degrees per clip.
struct WanderTuning {
    double open_ahead = 8.0;  ///< metres
    double band = 1.0;        ///< metres
};

struct CrowdTuning {
    /// m/s: a clip "moves" when its exit is at least this speed times its duration away
    /// (EscapeTable::moves): what the right of way and giving way count as standing still. Equal to the
    /// idle metric's threshold, so that an agent the metrics call idle is one the rules see waiting.
    double moving_speed = 0.25;
    EscapeTuning escape;
    StandNearWallsTuning stand_near_walls;
    LeaveInStrideTuning leave_in_stride;
    RightOfWayTuning right_of_way;
    GiveWayTuning give_way;
    LetThroughTuning let_through;
    KeepRightTuning keep_right;
    FaceAlongWallsTuning face_along_walls;
    StandingGapTuning standing_gap;
    LookAheadTuning look_ahead;
    FollowTuning follow;
    GoalTuning goal;
    WanderTuning wander;
};

/// Sets one field from "NAME=VALUE": NAME as the fields nest (`give_way.reach`, `look_ahead.on`,
/// `moving_speed`), or a flat name of the release before (`give_way_reach`, `look_ahead`; kept for one
/// release). Booleans: true/false, on/off, 1/0; numbers as written, finite. Throws std::invalid_argument
/// naming the field and the value on a bad one (an unknown name: with the fields there are).
void set_tuning(CrowdTuning& tuning, const std::string& assignment);

}  // namespace mobb::crowd
