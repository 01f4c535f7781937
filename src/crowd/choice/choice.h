// One crowd choice point (paper section 5): its candidates, drawn from the choice point's own random
// stream and put in order by the policy, placed in the world, and tested against what the other agents
// reserved. In the avoiding modes a candidate is taken only with a free escape (plan/escape.h): its plan -
// the clip, the clips that stop the agent, the ground it then holds - must be free; when no candidate's
// is, the agent takes its own escape, which the others were planned around. The rules that shape the
// choice are units of their own (rules/, a header each: their tuning, state and function); evaluate()
// applies them in order. Evaluations only read the reserved state, so the choice points of one frame run
// in parallel.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "collision/batch_grid.h"
#include "plan/choice_queries.h"
#include "plan/crowd_state.h"
#include "rules/follow.h"
#include "rules/give_way.h"
#include "rules/leave_in_stride.h"
#include "rules/look_ahead.h"
#include "rules/right_of_way.h"
#include "rules/standing_gap.h"
#include "rules/take_escape.h"

namespace mobb::crowd {

/// How a choice point ended.
enum class Outcome : std::uint8_t {
    Candidate,   ///< a candidate with a free plan (or, in random mode, the random pick)
    Escape,      ///< none was free: the agent's own escape (its next stopping clip, or one more held clip)
    Arrived,     ///< the agent is at its goal: it stands there (a free idle clip, then its held ground)
    Fallback,    ///< nothing free and no escape left: the least bad candidate
    RightOfWay,  ///< none was free, but the agent had waited long enough and a moving candidate was free once
                 ///< the other agents whose reservations it met took other ways to stop (Reroute), or
                 ///< free but for the standing gap (no Reroute then): rules/right_of_way.h
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

    int agent() const { return base_.agent; }
    Outcome outcome() const { return outcome_; }
    /// The clip taken and what is reserved beyond it.
    const BoxedClip& taken() const { return taken_; }
    const Plan& plan() const { return plan_; }
    /// The other agents' plans that gave way (Outcome::RightOfWay).
    const std::vector<Reroute>& reroutes() const { return right_of_way_.reroutes; }
    /// The boxes the commit changes beyond the agent's own released pieces: the taken clip, its plan, and
    /// the new and released boxes of the reroutes (for the frame's check of later choice points), appended
    /// to `out` (no list made per choice point).
    void boxes(std::vector<SpaceTimeBox>& out) const;
    const PlacedCandidate& candidate(int k) const { return placed_[std::size_t(k)]; }
    /// The record's choice point; `pruned` is left to the commit (it depends on the live count).
    ChoicePoint& point() { return queries_.point(); }
    int queried() const { return queries_.queried(); }
    std::optional<SpaceTimeBox> queried_bounds() const { return queries_.queried_bounds(); }
    std::uint64_t near_total() const { return queries_.near_total(); }
    std::uint64_t root_rejected() const { return queries_.root_rejected(); }
    /// The clip-against-clip queries in the order run, their choice left 0 (kept if log_queries).
    const std::vector<LoggedQuery>& log() const { return queries_.log(); }
    /// The clips the look-ahead intends after the one taken (ChoicePoint::intended; empty without one).
    const std::vector<SearchStep>& intended() const { return intended_; }
    /// What the look-ahead learned (LookAhead::learned; empty without one), for the agent's LearnedCost.
    const std::vector<std::array<double, 3>>& learned() const { return look_ahead_.learned; }

private:
    void order(const CrowdState& s);
    const PlacedCandidate& place(const CrowdState& s, int k);
    bool route_free(const CrowdState& s, int k, const BoxedClip& c, const std::vector<int>& route, Plan& plan,
                    std::size_t& refused);
    void take_deferred();
    bool try_right_of_way(const CrowdState& s, int end);
    void reset();
    bool try_candidate(const CrowdState& s, int k, const PlacedCandidate& c);
    bool try_routes(const CrowdState& s, int k, const BoxedClip& clip, std::uint32_t crowded);
    void evaluate_random(const CrowdState& s);
    bool take_escape(const CrowdState& s);
    void fall_back(const CrowdState& s);
    void take(int k, Outcome how);

    ChoiceBase base_;         // whose, when and where: every candidate starts there
    std::vector<int> drawn_;  // candidate clips in the stream's random order
    std::vector<int> order_;  // the same in the policy's order, for the current evaluation
    std::vector<int> next_;   // scratch: the order being made
    std::vector<SearchStep> intended_;
    std::vector<PlacedCandidate> placed_;  // order_[0 .. placed_.size()) placed
    int random_pick_ = 0;                  // random mode: index of the clip taken
    bool arriving_ = false;                // at its goal: stops as soon as it can
    Outcome outcome_ = Outcome::Candidate;
    BoxedClip taken_;
    Plan plan_;
    ChoiceQueries queries_;  // its queries and its record
    // The rules' state (rules/).
    LookAheadState look_ahead_;
    GiveWayState give_way_;
    RightOfWayState right_of_way_;
};

}  // namespace mobb::crowd
