#include "choice/choice.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mobb/core/assert.h"
#include "mobb/util/random.h"

namespace mobb::crowd {

void Choice::prepare(const CrowdState& s, int agent, std::int64_t frame) {
    base_.agent = agent;
    base_.frame = frame;
    util::Random rng = util::Random::stream(s.options.seed, std::uint64_t(agent), std::uint64_t(frame));
    const Agent& a = s.agents[std::size_t(agent)];
    const MotionGraph& g = s.graph;
    std::vector<int>& order = drawn_;
    base_.place = a.start;
    if (a.clips.empty()) {
        order = g.clips[std::size_t(rng.below(int(g.clips.size())))].successors;
    } else {
        const PlacedClip& last = a.clips.back();
        order = g.clips[std::size_t(last.clip)].successors;
        base_.place = g.next(last.place, last.clip);
    }
    if (order.empty()) throw std::invalid_argument("crowd: a graph clip has no successors");
    base_.place.t0 = double(frame) * g.dt();  // on the global grid, not accumulated
    base_.m = Rigid2::of(base_.place);
    for (std::size_t k = order.size(); k > 1; --k) std::swap(order[k - 1], order[std::size_t(rng.below(int(k)))]);
    random_pick_ = rng.below(int(order.size()));
    order_.clear();
    placed_.clear();
}

// The policy's order of the drawn candidates, from the state as it is now (the neighbours may have
// moved since a first evaluation), then the look-ahead's (look_ahead.h); placements are kept only while
// the order is unchanged.
void Choice::order(const CrowdState& s) {
    const Agent& a = s.agents[std::size_t(base_.agent)];
    ChoiceSite site{base_.agent, base_.place, a.goal(), a.stops_at_goal(), a.choices_waited, false, std::nullopt, {}};
    site.arrived = base_.frame >= a.start_frame && s.policy.arrived(site);
    if (s.options.tuning.follow.on) site.way = s.policy.heading(site);
    arriving_ = site.arrived;
    const double reach = s.policy.neighbourhood();
    if (reach == 0 && !order_.empty()) return;  // re-evaluated: what the order depends on is the same
    if (reach > 0) {
        const SpaceTimeBox around{
            base_.place.x - reach,
            base_.place.y - reach,
            base_.place.x + reach,
            base_.place.y + reach,
            base_.frame,
            base_.frame + std::int64_t(std::llround(s.options.tuning.goal.neighbours_ahead / s.graph.dt()))};
        LeaderFacing leader;
        for (int id : queries_.pieces_near(s, around)) {
            const Piece& p = s.pieces[std::size_t(id)];
            const std::optional<double> facing = leader(s.options.tuning.follow, s, p.agent);
            const Agent& other = s.agents[std::size_t(p.agent)];
            const auto goal = other.arrived ? std::nullopt : other.goal();
            if (p.kind == Piece::Held) site.neighbours.push_back({{p.hold.x, p.hold.y}, facing, goal, p.agent});
            if (p.kind == Piece::Clip)
                site.neighbours.push_back(
                    {{0.5 * (p.clip.box.x0 + p.clip.box.x1), 0.5 * (p.clip.box.y0 + p.clip.box.y1)},
                     facing,
                     goal,
                     p.agent});
        }
    }
    next_ = drawn_;
    s.policy.order(site, next_);
    look_ahead(s.options.tuning.look_ahead, s.options.tuning.follow, s, base_, site, queries_, next_, look_ahead_);
    if (next_ != order_) placed_.clear();
    std::swap(order_, next_);
}

const PlacedCandidate& Choice::place(const CrowdState& s, int k) {
    MOBB_ASSERT(k >= 0 && std::size_t(k) < order_.size());
    const Rigid2& m = base_.m;
    while (int(placed_.size()) <= k) {
        const int clip = order_[placed_.size()];
        // The random mode ranks candidates leaving the world; the others meet the walls instead.
        const World* world = s.policy.avoids() ? nullptr : &s.options.world;
        placed_.push_back(place_clip(s.outlines[std::size_t(clip)], clip,
                                     std::int64_t(s.graph.clips[std::size_t(clip)].path.size()), base_.place, m,
                                     base_.frame, world));
    }
    return placed_[std::size_t(k)];
}

// Whether candidate k's plan along `route` is free of the others (its clip was tested already), tested
// piece by piece as it is built. When an escape clip is not, `refused` is the route's prefix that
// placed it (its length; 0 otherwise).
bool Choice::route_free(const CrowdState& s, int k, const BoxedClip& c, const std::vector<int>& route, Plan& plan,
                        std::size_t& refused) {
    refused = 0;
    return build_plan(s, c, route, plan, [&](const Piece& piece) {
        if (queries_.candidate_free(s, k, piece, Hits::Stop)) return true;
        if (piece.kind == Piece::Clip) refused = std::size_t(piece.index);
        return false;
    });
}

void Choice::take(int k, Outcome how) {
    MOBB_ASSERT(k >= 0 && std::size_t(k) < placed_.size());  // tried, so placed
    const PlacedCandidate& c = placed_[std::size_t(k)];
    taken_ = {c.clip, c.place, base_.frame, c.box, base_.m};
    outcome_ = how;
    point().taken = c.clip;
    intended_after(look_ahead_, k, intended_);
}

// Nothing is free and the agent's escape cannot go on: the candidate that stays clear of walls and
// obstacles with the fewest collisions (its queries run in full), its first route reserved unchecked.
void Choice::fall_back(const CrowdState& s) {
    point().fallback = true;
    int best = -1;
    std::pair<int, int> best_key{1 << 30, 1 << 30};
    for (int k = 0; k < int(order_.size()); ++k) {
        const PlacedCandidate& c = place(s, k);
        if (int(point().candidates.size()) <= k) point().candidates.push_back({});
        point().candidates[std::size_t(k)] = Candidate{};
        point().candidates[std::size_t(k)].clip = c.clip;
        Piece mine;
        mine.clip = {c.clip, c.place, base_.frame, c.box, base_.m};
        queries_.candidate_free(s, k, mine, Hits::Count);
        const Candidate& cand = point().candidates[std::size_t(k)];
        const std::pair<int, int> key{cand.meets_solid ? 1 : 0, cand.hits};
        if (key < best_key) best = k, best_key = key;
    }
    take(best, Outcome::Fallback);
    const auto& routes = s.escapes.routes[std::size_t(taken_.clip)];
    plan_ = routes.empty() ? Plan{} : plan_along(s, taken_, routes.front());
}

// The paper's timing mode: every candidate's queries in full, then the random pick, nothing reserved.
void Choice::evaluate_random(const CrowdState& s) {
    for (int k = 0; k < int(order_.size()); ++k) {
        const PlacedCandidate& c = place(s, k);
        point().candidates.emplace_back().clip = c.clip;
        point().candidates.back().leaves_world = c.leaves_world;
        Piece mine;
        mine.clip = {c.clip, c.place, base_.frame, c.box, base_.m};
        queries_.candidate_free(s, k, mine, Hits::Count);
    }
    take(random_pick_, Outcome::Candidate);
    plan_ = Plan{};
}

// Forgets the last choice point's outcome and counters; keeps the candidates' memory, when the record
// left it.
void Choice::reset() {
    queries_.start(base_.agent, base_.frame);
    look_ahead_.learned.clear();
    intended_.clear();
    right_of_way_.reroutes.clear();
    outcome_ = Outcome::Candidate;
}

// The steps of a choice point, in order (the rules: rules/, a header each):
//  1. the candidates' order: the policy's, then the look-ahead's (look_ahead.h, past the reservations of
//     the leaders it follows: follow.h) - order();
//  2. an agent not started yet, or at its goal for good, takes its escape (take_escape.h);
//  3. the candidates in that order (try_candidate): the first is taken whose clip is free and leaves in
//     stride (leave_in_stride.h), or one of whose escape routes - but those that stop within the standing
//     gap of another (standing_gap.h) - has a free plan; a free walk passing an agent that waits is
//     deferred (give_way.h), and taken at the first candidate that does not move, or when none is left;
//  4. with the right of way (right_of_way.h), before the first candidate that does not move and after the
//     last, the moving candidates again, past the reservations of agents that then stop another way;
//  5. the agent's own escape (take_escape.h), and last the fallback.
void Choice::evaluate(const CrowdState& s) {
    reset();
    order(s);
    point().candidates.reserve(order_.size());
    if (!s.policy.avoids()) return evaluate_random(s);
    const Agent& a = s.agents[std::size_t(base_.agent)];
    if (base_.frame < a.start_frame || a.arrived) {
        if (!take_escape(s)) return fall_back(s);
        if (a.arrived) outcome_ = Outcome::Arrived;
        return;
    }
    // With the right of way, the moving candidates tried so far get a second chance before the agent
    // settles for one that does not move.
    bool right_of_way = has_right_of_way(s.options.tuning.right_of_way, a, base_.frame, s.graph.dt(), arriving_);
    give_way_.deferred = -1;
    for (int k = 0; k < int(order_.size()); ++k) {
        const PlacedCandidate& c = place(s, k);
        const bool moves = s.escapes.moves[std::size_t(c.clip)];
        if (give_way_.deferred >= 0 && !moves) return take_deferred();
        if (right_of_way && !moves) {
            if (try_right_of_way(s, k)) return;
            right_of_way = false;
        }
        if (try_candidate(s, k, c)) return;
    }
    if (give_way_.deferred >= 0) return take_deferred();
    if (right_of_way && try_right_of_way(s, int(order_.size()))) return;
    if (!take_escape(s)) fall_back(s);
}

// Candidate k, placed as c: taken when its clip is free of the others and it leaves in stride
// (leave_in_stride.h: no stop beyond the exit), or one of its escape routes is free too (try_routes).
// Returns whether it was taken.
bool Choice::try_candidate(const CrowdState& s, int k, const PlacedCandidate& c) {
    point().candidates.emplace_back().clip = c.clip;
    Piece mine;
    mine.clip = {c.clip, c.place, base_.frame, c.box, base_.m};
    if (!queries_.candidate_free(s, k, mine, Hits::Stop)) return false;
    const Agent& a = s.agents[std::size_t(base_.agent)];
    if (leaves_in_stride(s.options.tuning.leave_in_stride, s.graph, a, c, s.options.goal_radius)) {
        plan_ = Plan{};
        take(k, Outcome::Candidate);
        return true;
    }
    const std::uint32_t crowded = crowded_routes(s.options.tuning.standing_gap, s, base_, c.clip, queries_);
    if (try_routes(s, k, mine.clip, crowded)) return true;
    point().candidates.back().crowded = crowded != 0 && give_way_.deferred != k;
    return false;
}

// Candidate k's escape routes in turn, but those that would stop too close to another (`crowded`, a bit
// per route: standing_gap.h): the first whose plan is free of the others is taken - or deferred, when the
// clip moves and passes an agent that waits (give_way.h). Returns whether it was taken.
bool Choice::try_routes(const CrowdState& s, int k, const BoxedClip& clip, std::uint32_t crowded) {
    const auto& routes = s.escapes.routes[std::size_t(clip.clip)];
    const std::vector<int>* refused_route = nullptr;
    std::size_t refused = 0;
    for (std::size_t r = 0; r < routes.size(); ++r) {
        const std::vector<int>& route = routes[r];
        // The same escape clip at the same place as one refused already.
        if (refused > 0 && route.size() > refused &&
            std::equal(route.begin(), route.begin() + std::ptrdiff_t(refused), refused_route->begin()))
            continue;
        if (crowded >> r & 1) continue;
        refused_route = &route;
        if (!route_free(s, k, clip, route, plan_, refused)) continue;
        if (s.escapes.moves[std::size_t(clip.clip)] &&
            passes_waiting(s.options.tuning.give_way, s, base_, placed_[std::size_t(k)], give_way_.waiters)) {
            give_way_.defer(k, plan_);
            return false;
        }
        // Arrived when it stands where it is: an idle clip, held on the spot (it loops in place).
        const bool stops =
            arriving_ && s.escapes.kind[std::size_t(clip.clip)] == ClipKind::Idle && plan_.escape.empty();
        take(k, stops ? Outcome::Arrived : Outcome::Candidate);
        return true;
    }
    return false;
}

bool Choice::affected_by(const BatchGrid& chosen, int from, int below) const {
    return queries_.affected_by(chosen, from, below);
}

int Choice::last_change(const BatchGrid& chosen, int below) const { return queries_.last_change(chosen, below); }

// The right of way (right_of_way.h): a moving candidate among the first `end` again, past the
// reservations of agents that then stop another way.
bool Choice::try_right_of_way(const CrowdState& s, int end) {
    const CrowdTuning& t = s.options.tuning;
    const int k = take_right_of_way(t.right_of_way, s, base_, placed_, end, queries_, right_of_way_, plan_);
    if (k < 0) return false;
    take(k, Outcome::RightOfWay);
    return true;
}

// Giving way (give_way.h): the walk deferred, no later one being free and clear of waiting agents.
void Choice::take_deferred() {
    std::swap(plan_, give_way_.plan);
    take(give_way_.deferred, Outcome::Candidate);
}

// The agent's own escape (take_escape.h).
bool Choice::take_escape(const CrowdState& s) {
    if (!crowd::take_escape(s, base_, taken_, plan_)) return false;
    outcome_ = Outcome::Escape;
    point().taken = taken_.clip;
    return true;
}

void Choice::boxes(std::vector<SpaceTimeBox>& out) const {
    out.push_back(taken_.box);
    const auto add = [&](const Plan& p) {
        for (const BoxedClip& c : p.escape) out.push_back(c.box);
        if (p.hold) out.push_back(hold_box(*p.hold));
    };
    add(plan_);
    for (const Reroute& r : right_of_way_.reroutes) {
        add(r.plan);
        out.insert(out.end(), r.released.begin(), r.released.end());
    }
}

}  // namespace mobb::crowd
