// The look-ahead (LookAheadTuning; look_ahead.h): the bounded best-first search of clip sequences, and
// the rule that reorders a choice point's candidates by the sequences found.
#include "rules/look_ahead.h"

#include "mobb/core/assert.h"
#include "rules/follow.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobb::crowd {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kNoNode = std::numeric_limits<int>::max();
}  // namespace

// Weighted A* (Pohl 1970): the time to go weighs more in the order of search than in the score, so the
// search follows a sequence that gains ground to the horizon before widening. Rises with node.score for
// a weight >= 0 (each rounding is monotone), so a lower bound of the score gives a lower bound of this.
double LookAhead::priority(const Node& node) const {
    return node.elapsed + limits_.weight * (node.score - node.elapsed);
}

void LookAhead::score(Node& node) const {
    node.score = node.elapsed + (*to_go_)(node.end);
    node.exact = true;
}

// A step placed at step.place, whose rotation is m (Rigid2::of(step.place): one for all successors).
void LookAhead::push(const MotionGraph& graph, const SearchStep& step, const Rigid2& m, int parent, int first,
                     int depth, double elapsed) {
    const double seconds = elapsed + double(graph.clips[std::size_t(step.clip)].path.size()) * graph.dt();
    const Placement end = graph.next(step.place, m, step.clip);
    const double to_go = bound_ ? (*bound_)(end) : (*to_go_)(end);
    nodes_.push_back({step, parent, first, depth, seconds, seconds + to_go, end, !bound_});
    std::vector<Open>& open = open_[std::size_t(first)];
    open.push_back({priority(nodes_.back()), int(nodes_.size()) - 1});
    std::push_heap(open.begin(), open.end(), std::greater<>{});
    top_[std::size_t(first)] = open.front();
}

// top_[k] after candidate k's open list changed or it found its sequence.
void LookAhead::retop(std::size_t k) {
    top_[k] = best_[k] < 0 && !open_[k].empty() ? open_[k].front() : Open{kInfinity, kNoNode};
}

// The successors of a free node, each placed where it leaves the agent, on the global frame grid.
void LookAhead::expand(const MotionGraph& graph, int node) {
    const Node n = nodes_[std::size_t(node)];
    const GraphClip& clip = graph.clips[std::size_t(n.step.clip)];
    const std::int64_t frame = n.step.frame + std::int64_t(clip.path.size());
    Placement at = graph.next(n.step.place, Rigid2::of(n.step.place), n.step.clip);
    at.t0 = double(frame) * graph.dt();
    const Rigid2 m = Rigid2::of(at);
    for (int next : clip.successors) push(graph, {next, at, frame}, m, node, n.first, n.depth + 1, n.elapsed);
}

// The candidate still searching (no sequence yet, nodes open) whose least open node comes first, and
// into `second` the one whose comes next; -1: none.
int LookAhead::least(int& second) const {
    int first = -1;
    second = -1;
    const auto before = [&](std::size_t k, int other) { return other < 0 || top_[std::size_t(other)] > top_[k]; };
    for (std::size_t k = 0; k < top_.size(); ++k) {
        if (top_[k].node == kNoNode) continue;
        if (before(k, first))
            second = first, first = int(k);
        else if (before(k, second))
            second = int(k);
    }
    return first;
}

// The open node of least exact priority (ties: the lower node) of the candidates still searching, or -1:
// the node a search that scored every node as it pushed it would pop. A node pushed by its bound is
// scored when it comes to the top and goes back in by its exact priority. No key exceeds its node's
// exact priority (priority() rises with the score), so an exact key at the top is the least exact
// priority of all. The nodes of a candidate with its sequence are never read again.
int LookAhead::pop() {
    int second = -1;
    for (int k = least(second); k >= 0;) {
        std::vector<Open>& open = open_[std::size_t(k)];
        std::pop_heap(open.begin(), open.end(), std::greater<>{});
        const int i = open.back().node;
        Node& node = nodes_[std::size_t(i)];
        if (node.exact) {
            open.pop_back();
            retop(std::size_t(k));
            return i;
        }
        score(node);
        open.back().priority = priority(node);
        std::push_heap(open.begin(), open.end(), std::greater<>{});
        retop(std::size_t(k));
        if (second >= 0 && top_[std::size_t(k)] > top_[std::size_t(second)]) k = least(second);  // else still k
    }
    return -1;
}

// A candidate with nothing left open and no sequence to the horizon: every way on met a reservation.
void LookAhead::settle(int first, const LookAheadLimits& limits) {
    const auto k = std::size_t(first);
    if (!open_[k].empty() || best_[k] >= 0) return;
    score_[k] = reached_[k] + limits.dead_end;  // +infinity when the first clip itself was refused
}

// The best score among candidate k's open nodes. A bound at or above the best so far cannot lower it:
// only the others are scored.
double LookAhead::open_score(std::size_t k) {
    double best = kInfinity;
    for (const Open& o : open_[k]) {
        Node& node = nodes_[std::size_t(o.node)];
        if (!node.exact && node.score < best) score(node);
        best = std::min(best, node.score);
    }
    return best;
}

const std::vector<double>& LookAhead::search(const MotionGraph& graph, const std::vector<int>& first,
                                             const Placement& base, std::int64_t frame, const LookAheadLimits& limits,
                                             const Free& free, const ToGo& to_go, const ToGo& bound) {
    const std::size_t n = first.size();
    limits_ = limits;
    to_go_ = &to_go;
    bound_ = bound && limits.weight >= 0 ? &bound : nullptr;
    nodes_.clear();
    open_.resize(n);
    for (std::vector<Open>& open : open_) open.clear();
    top_.assign(n, {kInfinity, kNoNode});
    score_.assign(n, kInfinity);
    best_.assign(n, -1);
    reached_.assign(n, kInfinity);
    expanded_.clear();
    tested_ = 0;
    const Rigid2 m = Rigid2::of(base);
    for (std::size_t k = 0; k < n; ++k) push(graph, {first[k], base, frame}, m, -1, int(k), 1, 0.0);
    while (tested_ < limits.budget) {
        const int i = pop();
        if (i < 0) break;  // every candidate has its sequence or nothing left open
        const Node& node = nodes_[std::size_t(i)];
        const int k = node.first;
        ++tested_;
        if (!free(node.step)) {
            settle(k, limits);
            continue;
        }
        reached_[std::size_t(k)] = std::min(reached_[std::size_t(k)], node.score);
        if (node.depth >= limits.horizon) {
            best_[std::size_t(k)] = i;  // its sequence: the first to reach the horizon
            retop(std::size_t(k));
            score_[std::size_t(k)] = node.score;
            continue;
        }
        expanded_.push_back(i);
        expand(graph, i);
    }
    // What the budget left open: a candidate without a sequence to the horizon is scored by its best
    // open node (an estimate: its clips are not tested yet), behind the sequences found, as a dead end.
    for (std::size_t k = 0; k < n; ++k) {
        if (best_[k] >= 0) continue;
        if (open_[k].empty())
            settle(int(k), limits);
        else
            score_[k] = open_score(k) + limits.dead_end;
    }
    to_go_ = bound_ = nullptr;
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

namespace {

// Whether a searched step is free of the walls and of the others' pieces - past the reservations of the
// leaders the agent follows (follow.h) beyond its first clip, when it wants to go `way` - its queries
// counted for the choice point.
bool step_free(const FollowTuning& follow, const CrowdState& s, const ChoiceBase& base, std::optional<double> way,
               const SearchStep& step, ChoiceQueries& q, LeaderFacing& leader) {
    Piece piece;
    piece.agent = base.agent;
    piece.clip = frame_clip(s, step.clip, step.place, Rigid2::of(step.place), step.frame);
    const bool following = way && step.frame > base.frame;  // beyond the first clip
    const std::array<double, 2> from{base.place.x, base.place.y};
    return q.piece_free(
        s, piece, [&](int, const Piece& other) { return following && walks_on(follow, s, *way, from, other, leader); });
}

// The candidates of `io_order` by `score`, the lowest first; the order before breaks ties (io.ranked
// maps the new order to the old).
void reorder(const std::vector<double>& score, std::vector<int>& io_order, LookAheadState& io) {
    io.ranked.clear();
    for (std::size_t k = 0; k < io_order.size(); ++k) io.ranked.push_back({score[k], int(k)});
    std::stable_sort(io.ranked.begin(), io.ranked.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    io.scratch = io_order;
    for (std::size_t k = 0; k < io_order.size(); ++k) io_order[k] = io.scratch[std::size_t(io.ranked[k].second)];
}

}  // namespace

void look_ahead(const LookAheadTuning& t, const FollowTuning& follow, const CrowdState& s, const ChoiceBase& base,
                const ChoiceSite& site, ChoiceQueries& q, std::vector<int>& io_order, LookAheadState& io) {
    io.searched = false;
    const int horizon = s.policy.horizon(site);
    if (horizon <= 0 || !t.on) return;
    const LookAheadLimits limits{horizon, t.budget, t.dead_end, t.weight};
    LeaderFacing leader;
    const auto free = [&](const SearchStep& step) { return step_free(follow, s, base, site.way, step, q, leader); };
    const LearnedCost& learned = s.agents[std::size_t(base.agent)].learned;
    const Policy::Estimate estimate = s.policy.estimate(site);
    const auto to_go = [&](const Placement& end) {
        const double e = estimate.to_go(end);
        return t.learns ? std::max(e, learned.at(end.x, end.y)) : e;
    };
    const LookAhead::ToGo bound = estimate.bound;  // no more than estimate.to_go, nor than to_go then
    const std::vector<double>& score =
        io.search.search(s.graph, io_order, base.place, base.frame, limits, free, to_go, bound);
    io.searched = true;
    const double best = *std::min_element(score.begin(), score.end());
    if (best < std::numeric_limits<double>::infinity()) {
        io.search.learned(best, io.learned);
        io.learned.push_back({base.place.x, base.place.y, best});
    }
    reorder(score, io_order, io);
}

void intended_after(const LookAheadState& s, int k, std::vector<SearchStep>& out) {
    out.clear();
    if (!s.searched) return;
    const std::vector<SearchStep> sequence = s.search.sequence(s.ranked[std::size_t(k)].second);
    if (!sequence.empty()) out.assign(sequence.begin() + 1, sequence.end());
}

}  // namespace mobb::crowd
