#include "rules/leave_in_stride.h"

namespace mobb::crowd {

bool leaves_in_stride(const LeaveInStrideTuning& t, const MotionGraph& g, const Agent& a, const PlacedCandidate& c,
                      double goal_radius) {
    if (!t.on || a.at_goal != AtGoal::Leave || a.next_goal + 1 != a.goals.size()) return false;
    return reaches_goal(clip_end(g, c.clip, c.place), a.goals.back(), goal_radius);
}

}  // namespace mobb::crowd
