// How an agent picks its next clip at a choice point: the order its candidates are tried in (the first
// whose plan is free of collisions is taken) and when it stops for good. A new policy is one new file
// implementing Policy, plus its line in make_policy (policy.cpp).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/tuning.h"
#include "mobb/crowd/world/world.h"

namespace mobb::crowd {

enum class Selection {
    Wander,  ///< wander: candidates in random order, moving ones first; the first free plan is taken
    Random,  ///< a random successor whatever it collides with; every candidate's queries still run (the
             ///< paper's timing experiment: no escapes, no walls)
    Goal,    ///< candidates by how close they bring the agent to its goal (around obstacles); stop there
};
const char* to_string(Selection s);
/// "wander" | "random" | "goal" (and "avoid", its name until issue 44, for one release); throws
/// std::invalid_argument naming them.
Selection parse_selection(const std::string& name);

/// Where another agent near a choice point will be: the centre of a piece it reserved (metres), and the
/// way it faces (radians, world frame) when it is one to follow (CrowdTuning::follow): none when it
/// stopped for good, is about to, or has not set off.
struct Neighbour {
    std::array<double, 2> at;
    std::optional<double> facing;               ///< radians: where the clip it plays leaves it facing (rules/follow.h)
    std::optional<std::array<double, 2>> goal;  ///< metres: the goal it heads for now (none: arrived, or no goals)
    int agent = -1;                             ///< whose (an agent gives several: its clip, escape, held ground)
};

/// An agent at a choice point, as a policy sees it.
struct ChoiceSite {
    int agent = 0;
    Placement base;                             ///< where the next clip starts (t0: its start time)
    std::optional<std::array<double, 2>> goal;  ///< metres: the goal it heads for now
    bool stops = false;                         ///< it stands at that goal for good (its last; it stays)
    int choices_waited = 0;  ///< choice points in a row at which it waited (took its escape or stayed in place)
    bool arrived = false;    ///< Policy::arrived(): order() puts the ways to stop first
    /// Radians: the way it wants to go (Policy::heading) when it follows others (CrowdTuning::follow).
    std::optional<double> way;
    /// Where the other agents near it will be (Policy::neighbourhood() metres around it): the centres of
    /// what they reserved - the boxes of their clips, their held grounds - in the coming seconds.
    std::vector<Neighbour> neighbours;
};

class Policy {
public:
    virtual ~Policy() = default;
    virtual Selection kind() const = 0;
    /// Whether a choice keeps its agent's plan free of the others', the walls and the obstacles - the
    /// clip, the escape that would stop it, the ground it would hold - or just picks (the paper's timing
    /// mode: its queries run, nothing is reserved, walls are ignored).
    virtual bool avoids() const { return true; }
    /// Whether its agents keep the standing gap (CrowdTuning::standing_gap) from where others stand:
    /// wanderers do; agents with goals converge on purpose (a door, a circle's centre).
    virtual bool keeps_standing_gap() const { return false; }
    /// Whether its agents may stop with room to stand but not to turn from walls and obstacles
    /// (CrowdTuning::stand_near_walls): goal agents do, to queue in doors and corridors; a wanderer that
    /// stopped facing a wall with no room to turn stood there 42.9 s in a 10,000-agent run
    /// (bench/results/log.md, "Room to stop at walls").
    virtual bool stops_near_walls() const { return false; }
    /// Puts `candidates` (successor clips, already in the random order of the choice point's own stream)
    /// in the order they are tried.
    virtual void order(const ChoiceSite& site, std::vector<int>& candidates) const = 0;
    /// Whether the agent has arrived: it then stops as soon as a clip standing in place is free, and stays
    /// for good.
    virtual bool arrived(const ChoiceSite&) const { return false; }
    /// How far around the agent its neighbours are gathered for order() (0: not at all).
    virtual double neighbourhood() const { return 0; }
    /// How many clips deep the choice point searches ahead (look_ahead.h) before trying its candidates: 0
    /// keeps order()'s order alone. The first clips are then tried in the order of the best sequence
    /// each leads to, scored by its duration plus to_go() at its end (order() breaks ties).
    virtual int horizon(const ChoiceSite&) const { return 0; }
    /// The direction (radians, world frame) the agent wants to go from where it stands; none when it
    /// seeks no place (following, CrowdTuning::follow, compares it with the others' headings).
    virtual std::optional<double> heading(const ChoiceSite&) const { return std::nullopt; }
    /// The estimated seconds from `end` (where a searched sequence leaves the agent) to what it seeks.
    virtual double to_go(const ChoiceSite&, const Placement& /*end*/) const { return 0; }
    /// to_go() at one site as a function of the end alone, with what it reads of the site worked out
    /// once for the many ends a search scores, and a lower bound of it (never more) that is cheaper.
    struct Estimate {
        std::function<double(const Placement&)> to_go;
        std::function<double(const Placement&)> bound;  ///< empty: none cheaper than to_go
    };
    /// By default to_go() itself, without a bound. `site` must outlive the estimate.
    virtual Estimate estimate(const ChoiceSite& site) const {
        return {[this, &site](const Placement& end) { return to_go(site, end); }, {}};
    }
    /// An agent stopped for good at (x, y), holding a disk of radius r: the others plan around it. Called
    /// in commit order, never while choice points are evaluated.
    virtual void settled(double /*x*/, double /*y*/, double /*r*/) {}
};

/// What the policies may need: the graph (clips' ends, which clips stay in place), the world, the
/// goals (navigation fields around the obstacles are built for Goal) and the tuning. `in_place` has one
/// flag per clip.
struct PolicyContext {
    const MotionGraph& graph;
    const World& world;
    const std::vector<char>& in_place;
    std::vector<std::array<double, 2>> goals;  ///< every goal of the run (Goal)
    double goal_radius = 1.0;                  ///< metres: arrived within this of the goal
    CrowdTuning tuning;
    /// Metres from walls and obstacles an agent needs to stand, and to turn on the spot (the escape
    /// table's stand_clearance and turn_clearance: facing along walls, FaceAlongWallsTuning).
    double stand_clearance = 0, turn_clearance = 0;
};

std::unique_ptr<Policy> make_policy(Selection kind, const PolicyContext& context);

}  // namespace mobb::crowd
