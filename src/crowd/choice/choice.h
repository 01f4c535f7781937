// One crowd choice point (paper section 5): its candidates, drawn from the choice point's own random
// stream and put in order by the policy, placed in the world, and tested against what the other agents
// reserved. In the avoiding modes a candidate is taken only with a free escape (escape.h): its plan - the
// clip, the clips that stop the agent, the ground it then holds - must be free; when no candidate's is,
// the agent follows its own escape, which the others were planned around. Evaluations only read the
// reserved state, so the choice points of one frame run in parallel.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "choice/clip_outline.h"
#include "choice/escape.h"
#include "choice/look_ahead.h"
#include "collision/batch_grid.h"
#include "mobb/core/query.h"
#include "mobb/crowd/collision/broad_phase.h"
#include "mobb/crowd/collision/narrow_phase.h"
#include "mobb/crowd/options.h"
#include "mobb/crowd/policy/policy.h"

namespace mobb::crowd {

/// Ground an agent holds from frame `frame` on, for as long as it stands there: a disk of radius r.
struct Hold {
    double x = 0, y = 0, r = 0;
    std::int64_t frame = 0;
};

/// A graph clip at its place in the world, from global frame `frame` on, with its box (place_clip) and
/// its rotation m = Rigid2::of(place), computed once for every query it takes part in.
struct BoxedClip {
    int clip = 0;
    Placement place;
    std::int64_t frame = 0;
    SpaceTimeBox box;
    Rigid2 m;
};

/// What an agent reserves beyond the clip it plays: the clips that would stop it, then the held ground.
struct Plan {
    std::vector<BoxedClip> escape;
    std::optional<Hold> hold;
};

/// One thing in the broad phase, by id: a clip an agent committed to or reserved, or its held ground.
/// (Walls and obstacles never change: they have a grid of their own, CrowdState::solid_grid.)
struct Piece {
    enum Kind : std::uint8_t { Clip, Held } kind = Clip;
    int agent = -1;        ///< owner
    int choice = 0;        ///< the choice point (record order) whose plan holds it
    int index = 0;         ///< 0: the clip committed to; 1, 2, ...: its escape clips; -1: the held ground
    std::int64_t seq = 0;  ///< pieces placed before it have smaller ones (broad-phase ids are reused)
    BoxedClip clip;        ///< Clip
    Hold hold;             ///< Held
};

/// The space-time box a piece takes in the broad phase: its clip's, or its held disk's bounds from its
/// first frame on, for good.
SpaceTimeBox box_of(const Piece& piece);

/// Where clip `clip` of `g`, placed at `place`, leaves the agent's disk: its last sample in the world
/// (metres). Simulation::reach_goals and leaving in stride (Choice::leaves_after) both judge arrival by it
/// and reaches_goal, so they agree to the bit: a leaver holds no ground beyond the exit it reaches.
std::array<double, 2> clip_end(const MotionGraph& g, int clip, const Placement& place);
/// Whether a disk centred at `p` has reached `goal`: closer than `radius` metres (CrowdOptions::goal_radius).
bool reaches_goal(const std::array<double, 2>& p, const std::array<double, 2>& goal, double radius);

/// One agent of the simulation.
struct Agent {
    Placement start;
    std::int64_t start_frame = 0;              ///< stands at its start until then
    std::vector<std::array<double, 2>> goals;  ///< AgentSpec::goals, reached in turn
    std::size_t next_goal = 0;                 ///< the one it heads for now
    AtGoal at_goal = AtGoal::Stay;
    std::optional<std::int64_t> left_frame;  ///< it left the run then (AtGoal::Leave)
    std::vector<PlacedClip> clips;           ///< committed, in time order
    Plan plan;                               ///< reserved beyond its last clip
    std::vector<int> reserved;               ///< broad-phase ids of the plan's pieces
    bool arrived = false;                    ///< reached its goal: stays for good
    int stalled = 0;                         ///< choice points in a row it followed its escape or stayed in place
    std::int64_t moved_until = 0;  ///< where its last clip that moves (EscapeTable::moves) ended, or its start
    LearnedCost learned;           ///< what its look-aheads learned of the time to go (look_ahead.h)

    /// The goal it heads for now; nothing for an agent that wanders.
    std::optional<std::array<double, 2>> goal() const {
        if (next_goal >= goals.size()) return std::nullopt;
        return goals[next_goal];
    }
    /// Whether it stands at the goal it heads for for good: the last one, and it stays.
    bool stops_at_goal() const { return next_goal + 1 == goals.size() && at_goal == AtGoal::Stay; }
};

/// What a choice point reads, all of it frozen while a frame's choice points are evaluated.
struct CrowdState {
    const MotionGraph& graph;
    const std::vector<ClipOutline>& outlines;  ///< one per graph clip
    const NarrowPhase& narrow;
    const EscapeTable& escapes;
    const Policy& policy;
    const CrowdOptions& options;
    /// Metres held ground keeps from the solids: EscapeTable::stand_clearance where the policy's agents
    /// stop near walls (Policy::stops_near_walls, CrowdTuning::stand_near_walls), else turn_clearance.
    double hold_clearance;
    const std::vector<Polygon>& solids;  ///< World::solids(), by solid index
    const BroadPhase& solid_grid;        ///< the solids' bounds, by solid index (owner -1)
    const BroadPhase& broad;             ///< pieces live now
    const std::vector<Agent>& agents;
    const std::vector<Piece>& pieces;  ///< by broad-phase id
    const BroadPhase& waiting;         ///< agents that waited give_way_after or longer, by id (their ground)
    const std::vector<std::array<double, 2>>& waiting_at;  ///< per agent: where it waits (metres)
};

/// How a choice point ended.
enum class Outcome : std::uint8_t {
    Candidate,   ///< a candidate with a free plan (or, in random mode, the random pick)
    Escape,      ///< none was free: the agent's own escape (its next stopping clip, or one more held clip)
    Arrived,     ///< the agent is at its goal: it stands there (a free idle clip, then its held ground)
    Fallback,    ///< nothing free and no escape left: the least bad candidate
    RightOfWay,  ///< none was free, but the agent had waited long enough and a moving candidate was free once
                 ///< the other agents whose reservations it met took other ways to stop (Reroute), or
                 ///< free but for the standing gap (no Reroute then): right_of_way.cpp
};

/// Another agent's plan that gives way to a choice point's: what it reserves from now on, and the boxes
/// of the pieces it releases.
struct Reroute {
    int agent = 0;
    Plan plan;
    std::vector<SpaceTimeBox> released;
};

// Aligned to a cache line: neighbouring choice points are evaluated by different threads.
class alignas(64) Choice {
public:
    /// Draws the candidates of `agent` at `frame` from the stream (seed, agent, frame) and lets the
    /// policy order them; they are placed when first needed.
    void prepare(const CrowdState& s, int agent, std::int64_t frame);
    /// Runs the choice against the state as it is now; may be called again after commits.
    void evaluate(const CrowdState& s);
    /// Whether a plan committed in the same frame by a choice point in [from, below) (batch positions: the
    /// ones committed since the state this evaluation read, before this one) could change the evaluation:
    /// one of its boxes (new pieces, or released ones) overlaps a box this evaluation queried. Read-only:
    /// choice points check in parallel.
    bool affected_by(const BatchGrid& chosen, int from, int below) const;
    /// The last batch position before `below` whose plan's boxes in `chosen` overlap a box this evaluation
    /// queried (affected_by(chosen, that position, below) holds); -1 when none does.
    int last_change(const BatchGrid& chosen, int below) const;

    int agent() const { return agent_; }
    Outcome outcome() const { return outcome_; }
    /// The clip taken and what is reserved beyond it.
    const BoxedClip& taken() const { return taken_; }
    const Plan& plan() const { return plan_; }
    /// The other agents' plans that gave way (Outcome::RightOfWay).
    const std::vector<Reroute>& reroutes() const { return reroutes_; }
    /// The boxes the commit changes beyond the agent's own released pieces: the taken clip, its plan, and
    /// the new and released boxes of the reroutes (for the frame's check of later choice points), appended
    /// to `out` (no list made per choice point).
    void boxes(std::vector<SpaceTimeBox>& out) const;
    const PlacedCandidate& candidate(int k) const { return placed_[std::size_t(k)]; }
    /// The record's choice point; `pruned` is left to the commit (it depends on the live count).
    ChoicePoint& point() { return point_; }
    int queried() const { return int(queried_boxes_.size()); }
    std::uint64_t near_total() const { return near_total_; }
    std::uint64_t root_rejected() const { return root_rejected_; }
    /// The clip-against-clip queries in the order run, their choice left 0 (kept if log_queries).
    const std::vector<LoggedQuery>& log() const { return log_; }
    /// The clips the look-ahead intends after the one taken (ChoicePoint::intended; empty without one).
    const std::vector<SearchStep>& intended() const { return intended_; }
    /// What the look-ahead learned (LookAhead::learned; empty without one), for the agent's LearnedCost.
    const std::vector<std::array<double, 3>>& learned() const { return learned_; }

private:
    /// What a piece's queries do at a hit: stop; go on and count them all (fallback); or, with the right
    /// of way, go on past another agent's reservation that may yield (noting its owner) and stop at any
    /// other hit.
    enum class Hits { Stop, Count, Yield };

    void order(const CrowdState& s);
    void look_ahead(const CrowdState& s, const ChoiceSite& site, int horizon);
    bool piece_free(const CrowdState& s, const Piece& piece, const std::vector<int>* excluded, bool following = false);
    bool walks_on(const CrowdState& s, const Piece& other) const;
    void note_query(const SpaceTimeBox& box);
    void solids_near(const CrowdState& s, const SpaceTimeBox& box);
    bool free_of_solids(const CrowdState& s, int k, const Piece& mine, Hits hits);
    void count_query(const QueryStats& st);
    void record_query(const CrowdState& s, int k, const Piece& mine, CandidateQuery q, const QueryStats& st);
    const PlacedCandidate& place(const CrowdState& s, int k);
    bool free_of_others(const CrowdState& s, int k, const Piece& mine, Hits hits);
    std::uint32_t crowded_routes(const CrowdState& s, int k);
    bool may_yield(const CrowdState& s, const Piece& other) const;
    bool route_free(const CrowdState& s, int k, const BoxedClip& c, const std::vector<int>& route, Plan& plan,
                    std::size_t& refused);
    bool has_right_of_way(const CrowdState& s) const;
    bool passes_waiting(const CrowdState& s, int k);
    bool leaves_after(const CrowdState& s, const PlacedCandidate& c) const;
    void take_deferred();
    bool take_right_of_way(const CrowdState& s, int end);
    bool reroute_yielding(const CrowdState& s, const BoxedClip& c);
    bool reroute(const CrowdState& s, int owner);
    bool free_for_reroute(const CrowdState& s, const Piece& piece);
    void reset();
    bool try_candidate(const CrowdState& s, int k, const PlacedCandidate& c);
    bool try_routes(const CrowdState& s, int k, const BoxedClip& clip, std::uint32_t crowded);
    void evaluate_random(const CrowdState& s);
    bool take_escape(const CrowdState& s);
    bool hold_on(const CrowdState& s);
    void fall_back(const CrowdState& s);
    void take(int k, Outcome how);

    int agent_ = 0;
    std::int64_t frame_ = 0;
    std::vector<int> drawn_;                      // candidate clips in the stream's random order
    std::vector<int> order_;                      // the same in the policy's order, for the current evaluation
    std::vector<int> next_;                       // scratch: the order being made
    std::vector<int> scratch_;                    // scratch: next_ before the look-ahead's reorder
    std::vector<std::pair<double, int>> ranked_;  // scratch: (look-ahead score, policy rank)
    LookAhead search_;
    bool searched_ = false;              // order_ comes from the look-ahead (ranked_ maps it to its nodes)
    std::optional<double> way_heading_;  // following: the direction the agent wants to go (Policy::heading)
    std::vector<SearchStep> intended_;
    std::vector<std::array<double, 3>> learned_;
    Placement base_;                       // where and when the next clip starts
    Rigid2 base_m_;                        // Rigid2::of(base_): every candidate starts there
    std::vector<PlacedCandidate> placed_;  // order_[0 .. placed_.size()) placed
    int random_pick_ = 0;                  // random mode: index of the clip taken
    bool arriving_ = false;                // at its goal: stops as soon as it can
    std::vector<int> near_;                // scratch: broad-phase ids of one query
    std::vector<int> waiters_;             // scratch: agents waiting near a candidate
    int deferred_ = -1;                    // the first free moving candidate that passes a waiting agent
    Plan deferred_plan_;
    std::vector<SpaceTimeBox> queried_boxes_;  // every box the evaluation asked the broad phase about
    SpaceTimeBox queried_all_;                 // their union (bounding box)
    bool solids_asked_ = false;                // solid_free_ is set for this evaluation
    SpaceTimeBox solid_free_;                  // ground without solids (its time: all)
    std::uint64_t near_total_ = 0, root_rejected_ = 0;
    int last_hit_ = -1;  // broad-phase id of the other agent's piece that refused the last piece
    Outcome outcome_ = Outcome::Candidate;
    BoxedClip taken_;
    Plan plan_;
    std::vector<int> yielding_;  // right of way: owners of the reservations the plan being tried meets
    std::vector<int> excluded_;  // right of way: broad-phase ids released if it is taken (theirs and its own)
    std::vector<Piece> extra_;   // right of way: the new plan's pieces and the reroutes found so far
    std::vector<Reroute> reroutes_;
    ChoicePoint point_;
    std::vector<LoggedQuery> log_;
};

/// Graph clip `clip` placed at `p` (rotation m) from frame `frame` on, with its box.
BoxedClip frame_clip(const CrowdState& s, int clip, const Placement& p, const Rigid2& m, std::int64_t frame);

/// The plan of clip `c` along an escape route (EscapeTable::routes): its stopping clips chained after it
/// on the frame grid, and the held ground where the route's clip in place starts.
Plan plan_along(const CrowdState& s, const BoxedClip& c, const std::vector<int>& route);

// The plan of clip `c` along an escape route, built piece by piece: its stopping clips chained after it
// on the frame grid, then the held ground where the route's idle clip starts. Each piece goes to
// `accept` as it is placed, and the plan stops at the first it refuses; returns whether none was.
template <class Accept>
bool build_plan(const CrowdState& s, const BoxedClip& c, const std::vector<int>& route, Plan& plan, Accept&& accept) {
    // (The route's first i + 1 clips place its i-th piece: a refused escape clip refuses every route
    // sharing that prefix, which the caller skips.)
    const MotionGraph& g = s.graph;
    plan.escape.clear();
    plan.hold.reset();
    int prev = c.clip;
    Placement p = c.place;
    Rigid2 m = c.m;
    std::int64_t f = c.frame + std::int64_t(g.clips[std::size_t(prev)].path.size());
    Piece piece;
    for (std::size_t i = 0; i < route.size(); ++i) {
        p = g.next(p, m, prev);
        p.t0 = double(f) * g.dt();
        if (i + 1 == route.size()) break;  // the idle clip: the held ground starts with it
        m = Rigid2::of(p);
        piece.index = int(i) + 1;
        piece.clip = frame_clip(s, route[i], p, m, f);
        plan.escape.push_back(piece.clip);
        if (!accept(piece)) return false;
        prev = route[i];
        f += std::int64_t(g.clips[std::size_t(prev)].path.size());
    }
    plan.hold = Hold{p.x, p.y, s.escapes.hold_of(route.back()), f};
    piece.kind = Piece::Held;
    piece.index = -1;
    piece.hold = *plan.hold;
    return accept(piece);
}

/// The frame that never comes: held ground lasts until then.
inline constexpr std::int64_t kForever = std::numeric_limits<std::int64_t>::max();

/// The way agent `agent` faces at the end of the clip it plays (radians, world frame) when others may
/// follow it (follow.cpp); none when it stopped for good, ends that clip within follow_goal_reach of the
/// goal it stops at (it is about to), or has played no clip yet.
std::optional<double> leader_facing(const CrowdState& s, int agent);

/// Whether two held disks come closer than `gap` metres beyond touching.
inline bool holds_meet(const Hold& a, const Hold& b, double gap = 0) {
    const double dx = a.x - b.x, dy = a.y - b.y, r = a.r + b.r + gap;
    return dx * dx + dy * dy < r * r;
}

/// Whether piece `mine` of an agent's plan collides with another agent's piece: clips by the narrow
/// phase; a clip and held ground by their samples overlapping the held disk from its first frame on;
/// two held grounds by their disks.
bool pieces_collide(const CrowdState& s, const Piece& mine, const Piece& other, QueryStats* stats);

/// The broad-phase ids of the live pieces of agents other than `owner` whose boxes overlap `box`
/// (BroadPhase::query), in the order they were placed (Piece::seq): answers do not depend on which ids
/// were reused.
void query_pieces(const CrowdState& s, const SpaceTimeBox& box, int owner, std::vector<int>& out);
/// Whether it meets solid k: a clip's samples by disk_overlaps(); held ground when the solid is nearer
/// than CrowdState::hold_clearance.
bool meets_solid(const CrowdState& s, const Piece& mine, int k);

}  // namespace mobb::crowd
