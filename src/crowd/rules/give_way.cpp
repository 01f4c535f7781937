#include "rules/give_way.h"

#include <limits>

namespace mobb::crowd {

bool passes_waiting(const GiveWayTuning& t, const CrowdState& s, const ChoiceBase& base, const PlacedCandidate& c,
                    std::vector<int>& scratch) {
    if (!t.on) return false;
    const SpaceTimeBox& b = c.box;
    s.waiting.query(
        {b.x0, b.y0, b.x1, b.y1, std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()},
        base.agent, scratch);
    if (scratch.empty()) return false;
    const double r2 = t.reach * t.reach;
    for (const Sample& x : s.graph.clips[std::size_t(c.clip)].path.samples) {
        const double px = base.m.apply_x(x.x, x.y), py = base.m.apply_y(x.x, x.y);
        for (int w : scratch) {
            const auto& at = s.waiting_at[std::size_t(w)];
            if ((px - at[0]) * (px - at[0]) + (py - at[1]) * (py - at[1]) < r2) return true;
        }
    }
    return false;
}

bool waits(const GiveWayTuning& t, const Agent& a, std::int64_t end, double dt, bool avoids) {
    return t.on && avoids && !a.arrived && a.plan.hold && double(end - a.waiting_since) * dt >= t.after;
}

SpaceTimeBox waiting_ground(const GiveWayTuning& t, const Hold& h) {
    return {h.x - t.reach,
            h.y - t.reach,
            h.x + t.reach,
            h.y + t.reach,
            std::numeric_limits<std::int64_t>::min(),
            std::numeric_limits<std::int64_t>::max()};
}

}  // namespace mobb::crowd
