// The right of way (CrowdTuning::right_of_way): an agent that has not moved for right_of_way_after
// seconds may take a moving candidate whose plan meets other agents' reservations - the escape clips and
// held ground beyond the clip they play, never the clip itself - when each of those agents (at most
// max_yielding, none at a choice point in the frame, none standing) has another escape route from the
// clip it plays, free of everything else and of the new plan. The other agent then reserves that route
// instead: safe as before, it just stops elsewhere. Priority to the agent that waited, as in Okumura et
// al.'s priority inheritance with backtracking (PIBT, 2019): the higher-priority agent pushes the lower
// ones, which plan again. The right of way also passes the standing gap: one that waited may stop close
// (keeping the gap there too made the idle tail longer: bench/results/log.md).
#include "choice/choice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobb::crowd {

// Whether another agent's piece may give way to an agent with the right of way: a reservation (escape
// clip or held ground, not the clip it plays nor where it started) of an agent that plays a clip moving
// beyond this frame (not at a choice point now, not standing, not at its goal).
bool Choice::may_yield(const CrowdState& s, const Piece& other) const {
    if (other.index == 0 || other.choice < 0) return false;
    const Agent& owner = s.agents[std::size_t(other.agent)];
    if (owner.arrived || owner.clips.empty()) return false;
    const PlacedClip& playing = owner.clips.back();
    const auto end = playing.start + std::int64_t(s.graph.clips[std::size_t(playing.clip)].path.size());
    return end > base_.frame && !s.escapes.in_place[std::size_t(playing.clip)];
}

// A hit on another agent's piece that a plan with the right of way goes past: a reservation that may
// yield, of an owner yielding already or of one more within max_yielding (noted in yielding_).
bool Choice::yields(const CrowdState& s, const Piece& other) {
    if (!may_yield(s, other)) return false;
    if (std::find(yielding_.begin(), yielding_.end(), other.agent) != yielding_.end()) return true;
    if (yielding_.size() >= std::size_t(s.options.tuning.right_of_way.max_yielding)) return false;
    yielding_.push_back(other.agent);
    return true;
}

bool Choice::has_right_of_way(const CrowdState& s) const {
    const Agent& a = s.agents[std::size_t(base_.agent)];
    return s.options.tuning.right_of_way.on && !arriving_ &&
           double(base_.frame - a.moved_until) * s.graph.dt() >= s.options.tuning.right_of_way.after;
}

// The moving candidates before `end` again, in order, now past the reservations that may yield (at most
// CrowdTuning::max_yielding owners): the first whose plan is free but for them, and whose owners all find
// another way to stop, is taken.
bool Choice::take_right_of_way(const CrowdState& s, int end) {
    for (int k = 0; k < end; ++k) {
        const PlacedCandidate& c = placed_[std::size_t(k)];
        if (!s.escapes.moves[std::size_t(c.clip)]) continue;
        Piece mine;
        mine.clip = {c.clip, c.place, base_.frame, c.box, base_.m};
        yielding_.clear();
        const auto yields = [&](int, const Piece& other) { return this->yields(s, other); };
        if (!queries_.candidate_free(s, k, mine, Hits::Stop, yields)) continue;
        const std::size_t owners = yielding_.size();
        for (const std::vector<int>& route : s.escapes.routes[std::size_t(c.clip)]) {
            yielding_.resize(owners);
            const bool free = build_plan(s, mine.clip, route, plan_, [&](const Piece& piece) {
                return queries_.candidate_free(s, k, piece, Hits::Stop, yields);
            });
            if (!free || !reroute_yielding(s, mine.clip)) continue;
            take(k, Outcome::RightOfWay);
            return true;
        }
    }
    reroutes_.clear();
    return false;
}

// Another way to stop for every owner in yielding_, each free of the new plan (clip c and plan_), of the
// reroutes found before it and of everything else but what the taking would release.
bool Choice::reroute_yielding(const CrowdState& s, const BoxedClip& c) {
    excluded_.clear();
    excluded_.insert(excluded_.end(), s.agents[std::size_t(base_.agent)].reserved.begin(),
                     s.agents[std::size_t(base_.agent)].reserved.end());
    for (int w : yielding_) {
        const auto& r = s.agents[std::size_t(w)].reserved;
        excluded_.insert(excluded_.end(), r.begin(), r.end());
    }
    extra_.clear();
    Piece p;
    p.agent = base_.agent;
    p.clip = c;
    extra_.push_back(p);
    for (const BoxedClip& e : plan_.escape) {
        p.clip = e;
        extra_.push_back(p);
    }
    if (plan_.hold) {
        p.kind = Piece::Held;
        p.hold = *plan_.hold;
        extra_.push_back(p);
    }
    reroutes_.clear();
    for (int w : yielding_)
        if (!reroute(s, w)) return false;
    return true;
}

// The first escape route of `owner` from the clip it plays whose pieces are free (free_for_reroute); it
// joins reroutes_ and extra_.
bool Choice::reroute(const CrowdState& s, int owner) {
    const Agent& a = s.agents[std::size_t(owner)];
    const PlacedClip& playing = a.clips.back();
    const BoxedClip c = frame_clip(s, playing.clip, playing.place, Rigid2::of(playing.place), playing.start);
    Plan plan;
    for (const std::vector<int>& route : s.escapes.routes[std::size_t(playing.clip)]) {
        const bool free = build_plan(s, c, route, plan, [&](Piece piece) {
            piece.agent = owner;
            return free_for_reroute(s, piece);
        });
        if (!free) continue;
        Reroute r{owner, plan, {}};
        for (int id : a.reserved) {
            const Piece& old = s.pieces[std::size_t(id)];
            r.released.push_back(box_of(old));
        }
        for (const BoxedClip& e : plan.escape) {
            Piece p;
            p.agent = owner;
            p.clip = e;
            extra_.push_back(p);
        }
        Piece h;
        h.kind = Piece::Held;
        h.agent = owner;
        h.hold = *plan.hold;
        extra_.push_back(h);
        reroutes_.push_back(std::move(r));
        return true;
    }
    return false;
}

// A piece of a reroute: free of everything but what the taking would release (excluded_), and of the
// extra pieces (the new plan, the reroutes found before it).
bool Choice::free_for_reroute(const CrowdState& s, const Piece& piece) {
    const auto released = [&](int id, const Piece&) {
        return std::find(excluded_.begin(), excluded_.end(), id) != excluded_.end();
    };
    if (!queries_.piece_free(s, piece, released)) return false;
    for (const Piece& e : extra_)
        if (e.agent != piece.agent && queries_.collide(s, piece, e)) return false;
    return true;
}

}  // namespace mobb::crowd
