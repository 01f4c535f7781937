#include "rules/take_escape.h"

#include <algorithm>

namespace mobb::crowd {

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

// One more idle clip on the held ground, all of its disks inside it (so free: the others planned around
// it). Idle clips loop exactly in place, so the next one fits too.
bool hold_on(const CrowdState& s, const ChoiceBase& base, BoxedClip& out_clip, Plan& out_plan) {
    const Agent& a = s.agents[std::size_t(base.agent)];
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
        if (!inside_hold(s, c, base.place, h)) continue;
        out_clip = frame_clip(s, c, base.place, base.m, base.frame);
        out_plan = Plan{{}, h};
        return true;
    }
    return false;
}

}  // namespace

bool take_escape(const CrowdState& s, const ChoiceBase& base, BoxedClip& out_clip, Plan& out_plan) {
    const Agent& a = s.agents[std::size_t(base.agent)];
    if (a.plan.escape.empty()) return hold_on(s, base, out_clip, out_plan);
    out_clip = a.plan.escape.front();
    out_plan.escape.assign(a.plan.escape.begin() + 1, a.plan.escape.end());
    out_plan.hold = a.plan.hold;
    return true;
}

}  // namespace mobb::crowd
