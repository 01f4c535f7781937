// The look-ahead (CrowdTuning::look_ahead; look_ahead.h): the bounded best-first search of clip sequences,
// and Choice::look_ahead, which reorders a choice point's candidates by the sequences found.
#include "choice/look_ahead.h"

#include "choice/choice.h"
#include "mobb/core/assert.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobb::crowd {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}

void LookAhead::push(const MotionGraph& graph, const SearchStep& step, int parent, int first, int depth, double elapsed,
                     const ToGo& to_go) {
    const double seconds = elapsed + double(graph.clips[std::size_t(step.clip)].path.size()) * graph.dt();
    const Placement end = graph.next(step.place, step.clip);
    const double score = seconds + to_go(end);
    nodes_.push_back({step, parent, first, depth, seconds, score, end});
    // Weighted A* (Pohl 1970): the time to go weighs more in the order of search than in the score, so
    // the search follows a sequence that gains ground to the horizon before widening.
    open_.push({seconds + limits_.weight * (score - seconds), int(nodes_.size()) - 1});
    ++pending_[std::size_t(first)];
}

// The successors of a free node, each placed where it leaves the agent, on the global frame grid.
void LookAhead::expand(const MotionGraph& graph, int node, const ToGo& to_go) {
    const Node n = nodes_[std::size_t(node)];
    const GraphClip& clip = graph.clips[std::size_t(n.step.clip)];
    const std::int64_t frame = n.step.frame + std::int64_t(clip.path.size());
    const Rigid2 m = Rigid2::of(n.step.place);
    Placement at = graph.next(n.step.place, m, n.step.clip);
    at.t0 = double(frame) * graph.dt();
    for (int next : clip.successors) push(graph, {next, at, frame}, node, n.first, n.depth + 1, n.elapsed, to_go);
}

// A candidate with nothing left open and no sequence to the horizon: every way on met a reservation.
void LookAhead::settle(int first, const LookAheadLimits& limits) {
    const auto k = std::size_t(first);
    if (pending_[k] > 0 || best_[k] >= 0) return;
    score_[k] = reached_[k] + limits.dead_end;  // +infinity when the first clip itself was refused
}

const std::vector<double>& LookAhead::search(const MotionGraph& graph, const std::vector<int>& first,
                                             const Placement& base, std::int64_t frame, const LookAheadLimits& limits,
                                             const Free& free, const ToGo& to_go) {
    const std::size_t n = first.size();
    limits_ = limits;
    nodes_.clear();
    open_ = {};
    score_.assign(n, kInfinity);
    best_.assign(n, -1);
    pending_.assign(n, 0);
    reached_.assign(n, kInfinity);
    expanded_.clear();
    tested_ = 0;
    for (std::size_t k = 0; k < n; ++k) push(graph, {first[k], base, frame}, -1, int(k), 1, 0.0, to_go);
    while (!open_.empty() && tested_ < limits.budget) {
        const int i = open_.top().node;
        open_.pop();
        const Node& node = nodes_[std::size_t(i)];
        const int k = node.first;
        --pending_[std::size_t(k)];
        if (best_[std::size_t(k)] >= 0) continue;  // it has its sequence: the first to reach the horizon
        ++tested_;
        if (!free(node.step)) {
            settle(k, limits);
            continue;
        }
        reached_[std::size_t(k)] = std::min(reached_[std::size_t(k)], node.score);
        if (node.depth >= limits.horizon) {
            best_[std::size_t(k)] = i;
            score_[std::size_t(k)] = node.score;
            continue;
        }
        expanded_.push_back(i);
        expand(graph, i, to_go);
    }
    // What the budget left open: a candidate without a sequence to the horizon is scored by its best
    // open node (an estimate: its clips are not tested yet), behind the sequences found, as a dead end.
    std::vector<double>& open_score = reached_;  // no longer needed as such
    for (std::size_t k = 0; k < n; ++k)
        if (best_[k] < 0 && pending_[k] == 0) settle(int(k), limits);
    for (std::size_t k = 0; k < n; ++k)
        if (best_[k] < 0 && pending_[k] > 0) open_score[k] = kInfinity;
    for (; !open_.empty(); open_.pop()) {
        const Node& node = nodes_[std::size_t(open_.top().node)];
        const auto k = std::size_t(node.first);
        if (best_[k] < 0 && pending_[k] > 0) open_score[k] = std::min(open_score[k], node.score);
    }
    for (std::size_t k = 0; k < n; ++k)
        if (best_[k] < 0 && pending_[k] > 0) score_[k] = open_score[k] + limits.dead_end;
    return score_;
}

void LookAhead::learned(double best, std::vector<std::array<double, 3>>& out) const {
    for (int i : expanded_) {
        const Node& n = nodes_[std::size_t(i)];
        out.push_back({n.end.x, n.end.y, best - n.elapsed});
    }
}

std::vector<SearchStep> LookAhead::sequence(int k) const {
    MOBB_ASSERT(k >= 0 && std::size_t(k) < best_.size());
    std::vector<SearchStep> out;
    for (int i = best_[std::size_t(k)]; i >= 0; i = nodes_[std::size_t(i)].parent)
        out.push_back(nodes_[std::size_t(i)].step);
    std::reverse(out.begin(), out.end());
    return out;
}

// The policy's order (next_) reordered by the best sequence each candidate leads to (look_ahead.h); the
// policy's order breaks ties.
void Choice::look_ahead(const CrowdState& s, const ChoiceSite& site, int horizon) {
    const CrowdTuning& t = s.options.tuning;
    const LookAheadLimits limits{horizon, t.look_ahead.budget, t.look_ahead.dead_end, t.look_ahead.weight};
    way_heading_ = site.way;
    const auto free = [&](const SearchStep& step) {
        Piece piece;
        piece.agent = base_.agent;
        piece.clip = frame_clip(s, step.clip, step.place, Rigid2::of(step.place), step.frame);
        const bool following = way_heading_ && step.frame > base_.frame;  // beyond the first clip
        const std::array<double, 2> from{base_.place.x, base_.place.y};
        return queries_.piece_free(s, piece, [&](int, const Piece& other) {
            return following && walks_on(s.options.tuning.follow, s, *way_heading_, from, other);
        });
    };
    const LearnedCost& learned = s.agents[std::size_t(base_.agent)].learned;
    const auto to_go = [&](const Placement& end) {
        const double estimate = s.policy.to_go(site, end);
        return t.look_ahead.learns ? std::max(estimate, learned.at(end.x, end.y)) : estimate;
    };
    const std::vector<double>& score = search_.search(s.graph, next_, base_.place, base_.frame, limits, free, to_go);
    searched_ = true;
    const double best = *std::min_element(score.begin(), score.end());
    if (best < std::numeric_limits<double>::infinity()) {
        search_.learned(best, learned_);
        learned_.push_back({base_.place.x, base_.place.y, best});
    }
    ranked_.clear();
    for (std::size_t k = 0; k < next_.size(); ++k) ranked_.push_back({score[k], int(k)});
    std::stable_sort(ranked_.begin(), ranked_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    scratch_ = next_;
    for (std::size_t k = 0; k < next_.size(); ++k) next_[k] = scratch_[std::size_t(ranked_[k].second)];
}

}  // namespace mobb::crowd
