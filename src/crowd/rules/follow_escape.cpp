// Following one's own escape (escape.h): when no candidate's plan is free, the agent plays its next
// stopping clip - the others planned around it - or, at its held ground, one more idle clip inside it.
#include "choice/choice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobb::crowd {

// The agent's own escape: its next stopping clip, else one more clip in place on its held ground.
bool Choice::take_escape(const CrowdState& s) {
    const Agent& a = s.agents[std::size_t(base_.agent)];
    if (!a.plan.escape.empty()) {
        taken_ = a.plan.escape.front();
        plan_.escape.assign(a.plan.escape.begin() + 1, a.plan.escape.end());
        plan_.hold = a.plan.hold;
        outcome_ = Outcome::Escape;
        point().taken = taken_.clip;
        return true;
    }
    return hold_on(s);
}

namespace {

// Whether every disk of clip `c` placed at `base` lies inside the held disk h.
bool inside_hold(const CrowdState& s, int c, const Placement& base, const Hold& h) {
    if (base.x == h.x && base.y == h.y) return s.escapes.hold_of(c) <= h.r;  // idle clips start on the anchor
    const Rigid2 m = Rigid2::of(base);
    for (const Sample& x : s.graph.clips[std::size_t(c)].path.samples) {
        const double dx = m.apply_x(x.x, x.y) - h.x, dy = m.apply_y(x.x, x.y) - h.y, room = h.r - x.r;
        if (room < 0 || dx * dx + dy * dy > room * room) return false;
    }
    return true;
}

}  // namespace

// One more idle clip on the held ground, all of its disks inside it (so free: the others planned around
// it). Idle clips loop exactly in place, so the next one fits too.
bool Choice::hold_on(const CrowdState& s) {
    const Agent& a = s.agents[std::size_t(base_.agent)];
    if (!a.plan.hold) return false;
    const Hold& h = *a.plan.hold;
    const MotionGraph& g = s.graph;
    const auto idle = [&](int c) { return s.escapes.kind[std::size_t(c)] == ClipKind::Idle; };
    std::vector<int> options;
    if (a.clips.empty()) {
        for (int c = 0; c < int(g.clips.size()); ++c)
            if (idle(c)) options.push_back(c);
    } else {
        for (int c : g.clips[std::size_t(a.clips.back().clip)].successors)
            if (idle(c)) options.push_back(c);
    }
    std::sort(options.begin(), options.end());
    for (int c : options) {
        if (!inside_hold(s, c, base_.place, h)) continue;
        taken_ = frame_clip(s, c, base_.place, base_.m, base_.frame);
        plan_ = Plan{{}, h};
        outcome_ = Outcome::Escape;
        point().taken = c;
        return true;
    }
    return false;
}

}  // namespace mobb::crowd
