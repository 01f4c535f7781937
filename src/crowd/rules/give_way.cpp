// Giving way (CrowdTuning::give_way): a free moving candidate whose clip passes within give_way_reach of
// an agent that has not moved for give_way_after seconds (CrowdState::waiting) is taken only when no
// later moving candidate is free and clear of such agents: walkers keep out of the way of those who
// wait, when they can, so that the ground they would walk into stays open. It only reorders free
// candidates: nothing is refused for it.
#include "choice/choice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobb::crowd {

void Choice::take_deferred() {
    std::swap(plan_, deferred_plan_);
    take(deferred_, Outcome::Candidate);
}

// Whether candidate k's clip passes within give_way_reach of an agent that waits (CrowdState::waiting);
// never with giving way off.
bool Choice::passes_waiting(const CrowdState& s, int k) {
    if (!s.options.tuning.give_way.on) return false;
    const PlacedCandidate& c = placed_[std::size_t(k)];
    const SpaceTimeBox& b = c.box;
    s.waiting.query(
        {b.x0, b.y0, b.x1, b.y1, std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()},
        base_.agent, waiters_);
    if (waiters_.empty()) return false;
    const double r2 = s.options.tuning.give_way.reach * s.options.tuning.give_way.reach;
    for (const Sample& x : s.graph.clips[std::size_t(c.clip)].path.samples) {
        const double px = base_.m.apply_x(x.x, x.y), py = base_.m.apply_y(x.x, x.y);
        for (int w : waiters_) {
            const auto& at = s.waiting_at[std::size_t(w)];
            if ((px - at[0]) * (px - at[0]) + (py - at[1]) * (py - at[1]) < r2) return true;
        }
    }
    return false;
}

}  // namespace mobb::crowd
