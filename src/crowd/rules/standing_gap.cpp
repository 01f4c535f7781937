#include "rules/standing_gap.h"

#include <algorithm>

namespace mobb::crowd {

std::uint32_t crowded_routes(const StandingGapTuning& t, const CrowdState& s, const ChoiceBase& base, int clip,
                             ChoiceQueries& q) {
    if (!t.on || !s.policy.keeps_standing_gap()) return 0;
    const double gap = t.width;
    const auto& ends = s.escapes.ends[std::size_t(clip)];
    if (ends.empty()) return 0;
    // Held ground lasts for good and clips do not: asked at the end of time, the broad phase answers with
    // held ground alone.
    SpaceTimeBox box{1e300, 1e300, -1e300, -1e300, kForever - 1, kForever};
    Hold at[EscapeTable::kMaxRoutes];
    for (std::size_t r = 0; r < ends.size(); ++r) {
        const auto& [x, y] = ends[r];
        at[r] = {base.m.apply_x(x, y), base.m.apply_y(x, y),
                 s.escapes.hold_of(s.escapes.routes[std::size_t(clip)][r].back()), base.frame};
        box.x0 = std::min(box.x0, at[r].x), box.y0 = std::min(box.y0, at[r].y);
        box.x1 = std::max(box.x1, at[r].x), box.y1 = std::max(box.y1, at[r].y);
    }
    const double reach = s.escapes.hold_radius + gap;
    box.x0 -= reach, box.y0 -= reach, box.x1 += reach, box.y1 += reach;
    const Hold here{base.place.x, base.place.y, s.escapes.hold_radius, 0};
    std::uint32_t crowded = 0;
    for (int id : q.pieces_near(s, box)) {
        const Piece& p = s.pieces[std::size_t(id)];
        if (p.kind != Piece::Held || holds_meet(here, p.hold, gap)) continue;
        for (std::size_t r = 0; r < ends.size(); ++r)
            if (holds_meet(at[r], p.hold, gap)) crowded |= 1u << r;
    }
    return crowded;
}

}  // namespace mobb::crowd
