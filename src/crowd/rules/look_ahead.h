// Look-ahead at a choice point: a bounded best-first search over clip sequences of the motion graph,
// each clip placed where the one before leaves the agent and tested, as it is reached, against what the
// other agents reserved (the same exact queries as the candidates). A sequence is scored by its duration
// plus the policy's estimate of the time still to go from where it ends (Policy::to_go); the first clips
// are then tried in the order of the best sequence each leads to. The agent commits the first clip of
// its choice (with its escape, checked as always) and re-plans at its next choice point.
//
// Sources: Lau and Kuffner, "Behavior Planning for Character Animation" (SCA 2005): best-first search of
// a behaviour graph to a horizon, re-planned as the character moves; Silver, "Cooperative Pathfinding"
// (AIIDE 2005): a window searched against the others' space-time reservations; Sung, Kovar and Gleicher
// (SCA 2005): motion-graph clips chained towards a goal with MOBB-style tests.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/tuning.h"
#include "plan/choice_queries.h"
#include "plan/crowd_state.h"

namespace mobb::crowd {

/// A clip of a searched sequence: graph clip `clip` placed at `place` (its t0 on the global frame grid)
/// from global frame `frame` on. The tester decides whether it is free.
struct SearchStep {
    int clip = 0;
    Placement place;
    std::int64_t frame = 0;
};

struct LookAheadLimits {
    int horizon = 3;      ///< clips in a sequence
    int budget = 96;      ///< steps tested per choice point (each: the broad phase and its exact queries)
    double dead_end = 0;  ///< seconds added to a first clip without a free sequence to the horizon
    double weight = 2;    ///< of the time to go in the order of search (weighted A*; 1: plain best-first)
};

class LookAhead {
public:
    using Free = std::function<bool(const SearchStep&)>;
    /// Estimated seconds from a placement to what the agent seeks.
    using ToGo = std::function<double(const Placement&)>;

    /// Searches from `first` (candidate clips, all starting at `base` at frame `frame`) and returns one
    /// score per candidate (seconds, lower is better): its sequence's duration plus to_go at its end - the
    /// first found to the horizon, all of its clips free; without one, dead_end more than its best open
    /// estimate (the budget ran out) or than its best free clip (every way on was refused); +infinity
    /// for a first clip refused itself. `bound`, when given, is a cheaper lower bound of to_go (never
    /// more): a step enters the open list by it and gets to_go only if it comes near the top - the same
    /// search, scores and sequences, with to_go computed for a fraction of the steps.
    const std::vector<double>& search(const MotionGraph& graph, const std::vector<int>& first, const Placement& base,
                                      std::int64_t frame, const LookAheadLimits& limits, const Free& free,
                                      const ToGo& to_go, const ToGo& bound = {});

    /// The best sequence found through candidate k (its first clip included; empty when none was free).
    std::vector<SearchStep> sequence(int k) const;
    int tested() const { return tested_; }

    /// What the search learned of the time to go (Korf's LRTA*, 1990; Koenig and Likhachev's RTAA*,
    /// AAMAS 2006): from the end of every clip it found free and expanded, the goal is at least `best`
    /// (the best score of the search) less the time to get there. Appends (end x, end y, seconds).
    void learned(double best, std::vector<std::array<double, 3>>& out) const;

private:
    struct Node {
        SearchStep step;
        int parent = -1;  ///< index into nodes_; -1 for a first clip
        int first = 0;    ///< the candidate it descends from
        int depth = 1;
        double elapsed = 0;  ///< seconds from the choice point to the end of this clip
        double score = 0;    ///< elapsed + to_go(end); elapsed + bound(end) until `exact`
        Placement end;       ///< where the clip leaves the agent
        bool exact = true;
    };
    struct Open {
        double priority;
        int node;
        bool operator>(const Open& o) const { return priority != o.priority ? priority > o.priority : node > o.node; }
    };

    void push(const MotionGraph& graph, const SearchStep& step, const Rigid2& m, int parent, int first, int depth,
              double elapsed);
    void expand(const MotionGraph& graph, int node);
    void retop(std::size_t k);
    int least(int& second) const;
    int pop();
    void settle(int first, const LookAheadLimits& limits);
    double open_score(std::size_t k);
    void score(Node& node) const;
    double priority(const Node& node) const;

    LookAheadLimits limits_;
    const ToGo* to_go_ = nullptr;  // during search()
    const ToGo* bound_ = nullptr;  // during search(): null when nodes enter the open list by to_go
    std::vector<Node> nodes_;
    std::vector<std::vector<Open>> open_;  // per candidate: its open nodes, a heap (least first)
    std::vector<Open> top_;                // per candidate still searching: its least open node (priority +inf: none)
    std::vector<double> score_;            // per candidate
    std::vector<int> best_;                // per candidate: node ending its best sequence (-1: none)
    std::vector<double> reached_;          // per candidate: the best score of its free nodes
    std::vector<int> expanded_;            // free nodes whose successors were opened
    int tested_ = 0;
};

/// A choice point's look-ahead (LookAheadTuning): the search, and the order of the candidates it gave.
struct LookAheadState {
    LookAhead search;
    bool searched = false;  ///< the order comes from the search (ranked maps it to the search's candidates)
    /// Per candidate in the order given: its score, and its place in the order before (the search's k).
    std::vector<std::pair<double, int>> ranked;
    std::vector<int> scratch;                    ///< the order before
    std::vector<std::array<double, 3>> learned;  ///< appended: what the searches learned (LookAhead::learned)
};

/// Reorders `io_order` - the candidates, all starting at `base`, in the policy's order - by the best
/// sequence each leads to, the policy's order breaking ties, when the rule is on and the policy searches
/// (Policy::horizon(site) clips deep). Each step searched is tested with `q` against the walls and the
/// others' pieces - past the reservations of the leaders the agent follows beyond its first clip, when it
/// follows (site.way: FollowTuning) - and the policy's estimate of the time to go rises to what the agent
/// learned (Agent::learned, LookAheadTuning::learns). What this search learned is appended to io.learned.
void look_ahead(const LookAheadTuning& t, const FollowTuning& follow, const CrowdState& s, const ChoiceBase& base,
                const ChoiceSite& site, ChoiceQueries& q, std::vector<int>& io_order, LookAheadState& io);

/// The clips the search intends after candidate k of the order it gave (its best sequence less its first
/// clip), into `out`; none without a search.
void intended_after(const LookAheadState& s, int k, std::vector<SearchStep>& out);

}  // namespace mobb::crowd
