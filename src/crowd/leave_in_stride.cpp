// Leaving in stride (CrowdTuning::leave_in_stride): an agent whose last goal is an exit (AtGoal::Leave)
// and whose candidate clip ends within the goal radius of it leaves the run at that clip's end (the next
// choice point: Simulation::reach_goals), so the clip alone is its plan - it reserves no stop beyond the
// exit, which stays open for those behind. Safe as any plan: after the clip there is nobody to stop.
#include "choice.h"

#include <cmath>

namespace mobb::crowd {

bool Choice::leaves_after(const CrowdState& s, const PlacedCandidate& c) const {
    const Agent& a = s.agents[std::size_t(agent_)];
    if (!s.options.tuning.leave_in_stride || a.at_goal != AtGoal::Leave || a.next_goal + 1 != a.goals.size())
        return false;
    const Sample& end = s.graph.clips[std::size_t(c.clip)].path.samples.back();
    const std::array<double, 2>& exit = a.goals.back();
    const Rigid2 m = Rigid2::of(c.place);  // as Simulation::last_position places it: the same numbers
    const double x = m.apply_x(end.x, end.y), y = m.apply_y(end.x, end.y);
    return std::hypot(x - exit[0], y - exit[1]) < s.options.goal_radius;
}

}  // namespace mobb::crowd
