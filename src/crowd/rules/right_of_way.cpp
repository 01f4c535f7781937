#include "rules/right_of_way.h"

#include <algorithm>

namespace mobb::crowd {

bool may_reroute(const CrowdState& s, std::int64_t frame, const Piece& other) {
    if (other.index == 0 || other.choice < 0) return false;
    const Agent& owner = s.agents[std::size_t(other.agent)];
    if (owner.arrived || owner.clips.empty()) return false;
    const PlacedClip& playing = owner.clips.back();
    const auto end = playing.start + std::int64_t(s.graph.clips[std::size_t(playing.clip)].path.size());
    return end > frame && !s.escapes.in_place[std::size_t(playing.clip)];
}

namespace {

// A hit on another agent's piece that a plan with the right of way goes past: a reservation that may
// be rerouted, of an owner rerouted already or of one more within max_rerouted (noted in `rerouted`).
bool reroutable(const RightOfWayTuning& t, const CrowdState& s, std::int64_t frame, const Piece& other,
                std::vector<int>& rerouted) {
    if (!may_reroute(s, frame, other)) return false;
    if (std::find(rerouted.begin(), rerouted.end(), other.agent) != rerouted.end()) return true;
    if (rerouted.size() >= std::size_t(t.max_rerouted)) return false;
    rerouted.push_back(other.agent);
    return true;
}

// A piece of a reroute: free of everything but what the taking would release (io.excluded), and of the
// extra pieces (the new plan, the reroutes found before it).
bool free_for_reroute(const CrowdState& s, const Piece& piece, ChoiceQueries& q, const RightOfWayState& io) {
    const auto released = [&](int id, const Piece&) {
        return std::find(io.excluded.begin(), io.excluded.end(), id) != io.excluded.end();
    };
    if (!q.piece_free(s, piece, released)) return false;
    for (const Piece& e : io.extra)
        if (e.agent != piece.agent && q.collide(s, piece, e)) return false;
    return true;
}

// The first escape route of `owner` from the clip it plays whose pieces are free (free_for_reroute); it
// joins io.reroutes and io.extra.
bool reroute(const CrowdState& s, int owner, ChoiceQueries& q, RightOfWayState& io) {
    const Agent& a = s.agents[std::size_t(owner)];
    const PlacedClip& playing = a.clips.back();
    const BoxedClip c = frame_clip(s, playing.clip, playing.place, Rigid2::of(playing.place), playing.start);
    Plan plan;
    for (const std::vector<int>& route : s.escapes.routes[std::size_t(playing.clip)]) {
        const bool free = build_plan(s, c, route, plan, [&](Piece piece) {
            piece.agent = owner;
            return free_for_reroute(s, piece, q, io);
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
            io.extra.push_back(p);
        }
        Piece h;
        h.kind = Piece::Held;
        h.agent = owner;
        h.hold = *plan.hold;
        io.extra.push_back(h);
        io.reroutes.push_back(std::move(r));
        return true;
    }
    return false;
}

// Another way to stop for every owner in io.rerouted, each free of the new plan (clip c and `plan`), of
// the reroutes found before it and of everything else but what the taking would release.
bool reroute_all(const CrowdState& s, int agent, const BoxedClip& c, const Plan& plan, ChoiceQueries& q,
                 RightOfWayState& io) {
    io.excluded.clear();
    const std::vector<int>& mine = s.agents[std::size_t(agent)].reserved;
    io.excluded.insert(io.excluded.end(), mine.begin(), mine.end());
    for (int w : io.rerouted) {
        const auto& r = s.agents[std::size_t(w)].reserved;
        io.excluded.insert(io.excluded.end(), r.begin(), r.end());
    }
    io.extra.clear();
    Piece p;
    p.agent = agent;
    p.clip = c;
    io.extra.push_back(p);
    for (const BoxedClip& e : plan.escape) {
        p.clip = e;
        io.extra.push_back(p);
    }
    if (plan.hold) {
        p.kind = Piece::Held;
        p.hold = *plan.hold;
        io.extra.push_back(p);
    }
    io.reroutes.clear();
    for (int w : io.rerouted)
        if (!reroute(s, w, q, io)) return false;
    return true;
}

}  // namespace

bool has_right_of_way(const RightOfWayTuning& t, const Agent& a, std::int64_t frame, double dt, bool arriving) {
    return t.on && !arriving && double(frame - a.waiting_since) * dt >= t.after;
}

int take_right_of_way(const RightOfWayTuning& t, const CrowdState& s, const ChoiceBase& base,
                      const std::vector<PlacedCandidate>& placed, int end, ChoiceQueries& q, RightOfWayState& io,
                      Plan& out_plan) {
    const auto passes = [&](int, const Piece& other) { return reroutable(t, s, base.frame, other, io.rerouted); };
    for (int k = 0; k < end; ++k) {
        const PlacedCandidate& c = placed[std::size_t(k)];
        if (!s.escapes.moves[std::size_t(c.clip)]) continue;
        Piece mine;
        mine.clip = {c.clip, c.place, base.frame, c.box, base.m};
        io.rerouted.clear();
        if (!q.candidate_free(s, k, mine, Hits::Stop, passes)) continue;
        const std::size_t owners = io.rerouted.size();
        for (const std::vector<int>& route : s.escapes.routes[std::size_t(c.clip)]) {
            io.rerouted.resize(owners);
            const bool free = build_plan(s, mine.clip, route, out_plan, [&](const Piece& piece) {
                return q.candidate_free(s, k, piece, Hits::Stop, passes);
            });
            if (free && reroute_all(s, base.agent, mine.clip, out_plan, q, io)) return k;
        }
    }
    io.reroutes.clear();
    return -1;
}

}  // namespace mobb::crowd
