// Leaving in stride (CrowdTuning::leave_in_stride): an agent whose last goal is an exit (AtGoal::Leave)
// and whose candidate clip ends within the goal radius of it leaves the run at that clip's end (the next
// choice point: Simulation::reach_goals), so the clip alone is its plan - it reserves no stop beyond the
// exit, which stays open for those behind. Safe as any plan: after the clip there is nobody to stop.
#include "choice/choice.h"

namespace mobb::crowd {

bool Choice::leaves_after(const CrowdState& s, const PlacedCandidate& c) const {
    const Agent& a = s.agents[std::size_t(agent_)];
    if (!s.options.tuning.leave_in_stride.on || a.at_goal != AtGoal::Leave || a.next_goal + 1 != a.goals.size())
        return false;
    return reaches_goal(clip_end(s.graph, c.clip, c.place), a.goals.back(), s.options.goal_radius);
}

}  // namespace mobb::crowd
