// The standing gap (CrowdTuning::standing_gap; kept by the policies whose agents wander,
// Policy::keeps_standing_gap): no candidate is taken along an escape route whose held ground would come
// within standing_gap_width metres, beyond what the disks need, of another agent's held ground - unless
// the agent already stands that close to that ground (the test is then left out: it could never stop
// otherwise). Agents that stop leave room to pass between them instead of packing into knots whose every
// walk is refused and that untangle one slow clip at a time (the longest idle stretches:
// bench/results/log.md). A preference of the choice, not a collision: contacts keep the exact test.
#include "choice/choice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobb::crowd {

// Which routes of candidate k would hold ground within the standing gap of another agent's (bit r: route
// r), leaving out the held ground the agent already stands that close to (it could not stop otherwise);
// none when its policy keeps no gap or the rule is off.
std::uint32_t Choice::crowded_routes(const CrowdState& s, int k) {
    const CrowdTuning& tuning = s.options.tuning;
    if (!tuning.standing_gap.on || !s.policy.keeps_standing_gap()) return 0;
    const double gap = tuning.standing_gap.width;
    const int clip = placed_[std::size_t(k)].clip;
    const auto& ends = s.escapes.ends[std::size_t(clip)];
    if (ends.empty()) return 0;
    // Held ground lasts for good and clips do not: asked at the end of time, the broad phase answers with
    // held ground alone.
    SpaceTimeBox box{1e300, 1e300, -1e300, -1e300, kForever - 1, kForever};
    Hold at[EscapeTable::kMaxRoutes];
    for (std::size_t r = 0; r < ends.size(); ++r) {
        const auto& [x, y] = ends[r];
        at[r] = {base_.m.apply_x(x, y), base_.m.apply_y(x, y),
                 s.escapes.hold_of(s.escapes.routes[std::size_t(clip)][r].back()), base_.frame};
        box.x0 = std::min(box.x0, at[r].x), box.y0 = std::min(box.y0, at[r].y);
        box.x1 = std::max(box.x1, at[r].x), box.y1 = std::max(box.y1, at[r].y);
    }
    const double reach = s.escapes.hold_radius + gap;
    box.x0 -= reach, box.y0 -= reach, box.x1 += reach, box.y1 += reach;
    const Hold here{base_.place.x, base_.place.y, s.escapes.hold_radius, 0};
    std::uint32_t crowded = 0;
    for (int id : queries_.pieces_near(s, box)) {
        const Piece& p = s.pieces[std::size_t(id)];
        if (p.kind != Piece::Held || holds_meet(here, p.hold, gap)) continue;
        for (std::size_t r = 0; r < ends.size(); ++r)
            if (holds_meet(at[r], p.hold, gap)) crowded |= 1u << r;
    }
    return crowded;
}

}  // namespace mobb::crowd
