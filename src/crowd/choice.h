// One crowd choice point (paper section 5): its candidates, drawn from the choice point's own random
// stream, placed in the world, and tested against the clips other agents have committed to.
// Evaluations only read the committed state, so the choice points of one frame run in parallel.
#pragma once
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "batch_grid.h"
#include "mobb/core/query.h"
#include "mobb/crowd/broad_phase.h"
#include "mobb/crowd/crowd.h"

namespace mobb::crowd {

/// A candidate clip placed in the world: its space-time box and whether it leaves the world.
struct Placed {
    int clip = 0;
    Placement place;
    SpaceTimeBox box;
    bool outside = false;
    double excess = 0;  ///< metres farther outside than at the start (ranks fallbacks)
};

/// A clip's root positions reduced to their convex hull (clip frame, metres, counter-clockwise) and its
/// largest radius. A placed clip's world box and how far it leaves the world are maxima of convex
/// functions of the root position, so the hull's vertices give them: a few points instead of every sample.
struct ClipOutline {
    std::vector<std::array<double, 2>> hull;
    double r_max = 0;
};
ClipOutline outline_of(const Path& path);
std::vector<ClipOutline> outlines_of(const MotionGraph& g);

/// Places graph clip `clip` (outline `outline`) at `p` from global frame `frame` on. The box pads the
/// hull by r_max, so it holds every sample disk.
Placed place_clip(const ClipOutline& outline, int clip, std::int64_t frames, const Placement& p, std::int64_t frame,
                  const CrowdOptions& o);

/// One agent of the simulation: where it started and the clips it committed to, in time order.
struct Agent {
    Placement start;
    std::vector<PlacedClip> clips;
};

/// A committed clip by broad-phase id: whose it is (agent, index in its clips) and where it plays,
/// copied from the agent's clip so a query reads one compact entry.
struct Committed {
    int agent = 0, index = 0, clip = 0;
    Placement place;
};

/// What a choice point reads, all of it frozen while a frame's choice points are evaluated.
struct CrowdState {
    const MotionGraph& graph;
    const std::vector<ClipOutline>& outlines;  ///< one per graph clip
    const std::vector<Tree>& trees;
    const CrowdOptions& options;
    const BroadPhase& broad;  ///< committed clips still playing
    const std::vector<Agent>& agents;
    const std::vector<Committed>& committed;  ///< by broad-phase id
};

/// One narrow-phase query as run: the committed clip's broad-phase id and the answer.
struct Answer {
    int id = 0;
    bool hit = false;
    QueryStats stats;
};

// Aligned to a cache line: neighbouring choice points are evaluated by different threads.
class alignas(64) Choice {
public:
    /// Draws the candidates of `agent` at `frame` from the stream (seed, agent, frame); they are placed
    /// when first needed (in avoid mode most choices stop at an early candidate).
    void prepare(const CrowdState& s, int agent, std::int64_t frame);
    /// Runs the choice against the state as it is now; may be called again after commits. Answers of
    /// earlier evaluations are reused: a candidate's broad-phase list only grows between evaluations
    /// (new commits get larger ids), so its old queries are a prefix of its new ones.
    void evaluate(const CrowdState& s);
    /// Whether a clip chosen in the same frame by a choice point before this one (index < `below` in
    /// `chosen`) could change the evaluation: it overlaps the box of a candidate the evaluation queried
    /// the broad phase for, so it would have been queried. Read-only: choice points check in parallel.
    bool affected_by(const BatchGrid& chosen, int below) const;
    /// The same for one box.
    bool affected_by(const SpaceTimeBox& box) const;

    int agent() const { return agent_; }
    const Placed& candidate(int k) const { return placed_[std::size_t(k)]; }
    const Placed& taken() const { return placed_[std::size_t(taken_)]; }
    /// The record's choice point; `pruned` is left to the commit (it depends on the live count).
    ChoicePoint& point() { return point_; }
    /// Broad-phase queries run and the sum of their result sizes (for time_pairs and pruned).
    int queried() const { return queried_; }
    std::uint64_t near_total() const;
    std::uint64_t root_rejected() const { return root_rejected_; }
    /// The queries in the order run: (candidate index, broad-phase id, hit) (kept if log_queries).
    const std::vector<std::pair<int, Answer>>& log() const { return log_; }

private:
    const Placed& place(const CrowdState& s, int k);
    int count_hits(const CrowdState& s, int k, bool stop_at_hit);
    const Answer& ask(const CrowdState& s, int k, std::size_t pos, int id);
    int fallback_pick() const;

    int agent_ = 0;
    std::int64_t frame_ = 0;
    std::vector<int> order_;                  // candidate clips in test order
    Placement base_;                          // where and when the next clip starts
    std::vector<Placed> placed_;              // order_[0 .. placed_.size()) placed
    int random_pick_ = 0;                     // Selection::Random: index of the clip taken
    std::vector<std::vector<int>> near_;      // per candidate: broad-phase ids, ascending
    std::vector<std::vector<Answer>> asked_;  // per candidate: answers by position in near_
    int queried_ = 0, taken_ = -1;
    std::uint64_t root_rejected_ = 0;
    ChoicePoint point_;
    std::vector<std::pair<int, Answer>> log_;
};

}  // namespace mobb::crowd
