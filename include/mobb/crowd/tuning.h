// Every tuning number of the crowd's rules in one place: what it is, its unit and what it trades (after
// Box2D's constants.h and DetourCrowd's dtCrowdAgentParams). Each rule can be switched off - on
// the command line `mobb crowd --no-right-of-way`, `--no-give-way`, `--no-standing-gap`,
// `--no-look-ahead`, `--no-follow`, `--no-stand-near-walls`, `--no-leave-in-stride` - so a rule's effect
// is one command away, and any field is set by name with `mobb crowd --tune NAME=VALUE` (set_tuning()).
// What was measured to choose the values: bench/results/log.md, "Tuning: what was measured".
// Metrics keep their own thresholds (CrowdMetrics::kIdleSpeed): judging a run never changes how it runs.
#pragma once
#include <string>

namespace mobb::crowd {

struct CrowdTuning {
    /// m/s: a clip "moves" when its exit is at least this speed times its duration away
    /// (EscapeTable::moves). What the right of way and giving way count as standing still. Chosen equal
    /// to the idle metric's threshold, 0.25 m/s, so that an agent the metrics call idle is one the rules
    /// see waiting.
    double moving_speed = 0.25;

    // The escape (src/crowd/choice/escape.cpp): the clips that stop an agent, then the ground it holds. Always
    // on - it is what keeps the crowd collision-free - and bounded here.
    int escape_steps = 3;    ///< clips at most from a clip to a stop (longer chains: no route)
    int escape_routes = 16;  ///< routes kept per clip, the shortest first (<= EscapeTable::kMaxRoutes)
    /// Metres beyond the clips' footprint that held ground and starts keep from walls and obstacles
    /// (EscapeTable::stand_clearance, turn_clearance): slack for rounding.
    double wall_margin = 0.1;
    /// Stopping near walls (EscapeTable::stand_clearance; goal agents only: Policy::stops_near_walls):
    /// held ground needs room to stand (0.58 m from walls on the committed graph), not room to turn on the
    /// spot (0.98 m); a turn is tested against the walls where it is chosen, as every clip is. Trades the
    /// certainty that a stopped agent can turn round for ground to stop on in doors and corridors: a 2.4 m
    /// door keeps 1.24 m of it, not 0.44 m.
    bool stand_near_walls = true;

    /// Leaving in stride (src/crowd/rules/leave_in_stride.cpp): a clip that ends within the goal radius of an
    /// agent's exit (its last goal, AtGoal::Leave) is its whole plan - no stop reserved beyond the exit,
    /// where it leaves the run. Off, the exit holds each leaver's stop until it has left, and those behind
    /// queue for it.
    bool leave_in_stride = true;

    // The right of way (src/crowd/rules/right_of_way.cpp; Okumura et al.'s PIBT, 2019): an agent that has not
    // moved for `right_of_way_after` seconds may take a walk whose plan meets only the reservations of
    // at most `max_yielding` agents walking a clip, each of which then stops another way. Trades a
    // waiting agent's time against the others' detours.
    bool right_of_way = true;
    double right_of_way_after = 2.0;  ///< seconds without a moving clip
    int max_yielding = 2;             ///< agents whose reservations one taking may move

    // Giving way (src/crowd/rules/give_way.cpp): a free walk passing within `give_way_reach` metres of an agent
    // that has not moved for `give_way_after` seconds is taken only when no later free walk keeps clear
    // of such agents. Reorders, never refuses: trades a walker's detour for the waiting agent's way out.
    bool give_way = true;
    double give_way_after = 2.0;  ///< seconds
    double give_way_reach = 2.5;  ///< metres

    // The standing gap (src/crowd/rules/standing_gap.cpp): a policy that keeps it (wandering, not goal agents,
    // which converge on purpose) takes no escape route whose held ground comes within `standing_gap`
    // metres, beyond the disks, of another's. Trades where an agent may stop for room to pass between
    // those who stopped, so that stopped agents do not pack into knots that walkers cannot pass.
    bool standing_gap = true;
    double standing_gap_width = 0.45;  ///< metres

    // The look-ahead (src/crowd/choice/look_ahead.h; Lau and Kuffner 2005, Silver 2005): a goal agent searches
    // clip sequences `goal_horizon` clips deep, at most `look_ahead_budget` clips tested per choice
    // point; a first clip whose every sequence met a reservation ranks `look_ahead_dead_end` seconds
    // behind. The budget bounds a choice point's cost; most searches reach the horizon within it.
    bool look_ahead = true;
    int look_ahead_budget = 96;        ///< clips tested per choice point, at most
    double look_ahead_dead_end = 2.0;  ///< seconds
    /// Whether the look-ahead's estimate of a place rises to what earlier searches found (LearnedCost;
    /// Korf's LRTA*): a place an agent waited in fills up until another way scores better. Off (the
    /// policy's estimate alone), the queues jostle less but stay longer.
    bool look_ahead_learns = true;

    // Following (src/crowd/rules/follow.cpp; Silver 2005: reservations trusted within a window): a goal agent
    // follows the agents ahead of it - within `follow_angle` of its way (down its navigation field:
    // NavField::downhill) - that face its way, unless they end their clip within `follow_goal_reach` of
    // the goal they stop at: beyond its first clip its look-ahead plans past their reservations (escape
    // clips and held ground, never the clip they play), and its estimate of the time to go counts no
    // crowding for them. It waits in line behind them rather than walking round a queue it could join;
    // its first clip and that clip's escape are tested against everything, as always. Trades detours
    // round a queue for waiting in it: queues at doors and in corridors move sooner, crossings in the open
    // later (agents converging on one point follow one another into it).
    bool follow = true;
    double follow_angle = 0.8;       ///< radians (46 degrees) either side of the agent's way
    double follow_goal_reach = 3.0;  ///< metres: a leader this near its goal is about to stand there for good

    // The goal policy's estimate of the time to go (src/crowd/policy/policy_goal.cpp): path length at
    // `goal_walking` m/s, plus the turn to face down the path at `goal_turning` rad/s, plus
    // `goal_crowding` seconds per metre an end comes nearer than `goal_personal` to a neighbour. The
    // speeds are the committed graph's walking and turning clips', rounded. Crowding trades following
    // close (queues flow with less) against room where agents settle (late arrivals are hemmed in short
    // of their goals with less).
    double goal_walking = 1.3;    ///< m/s
    double goal_turning = 1.3;    ///< rad/s
    double goal_personal = 2.0;   ///< metres
    double goal_crowding = 1.2;   ///< seconds per metre
    int goal_patience = 3;        ///< choice points without moving on before trying candidates at random,
                                  ///< those that move first
    int goal_horizon = 3;         ///< clips searched ahead (about 3.6 s of the committed graph's clips)
    double nav_clearance = 0.45;  ///< metres the navigation fields keep from walls and obstacles
};

/// Sets one field from "NAME=VALUE" (booleans: true/false, on/off, 1/0; numbers as written, finite).
/// Throws std::invalid_argument naming the field and the value on a bad one (an unknown name: with the
/// fields there are).
void set_tuning(CrowdTuning& tuning, const std::string& assignment);

}  // namespace mobb::crowd
