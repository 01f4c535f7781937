// Leaving in stride (LeaveInStrideTuning): an agent whose last goal is an exit (AtGoal::Leave) and whose
// candidate clip ends within the goal radius of it leaves the run at that clip's end (the next choice
// point: Simulation::reach_goals), so the clip alone is its plan - it reserves no stop beyond the exit,
// which stays open for those behind. Safe as any plan: after the clip there is nobody to stop.
#pragma once
#include "mobb/crowd/tuning.h"
#include "plan/crowd_state.h"

namespace mobb::crowd {

/// Whether agent `a` leaves the run at the end of candidate `c`, so that the clip is its whole plan: its
/// last goal is an exit and the clip ends within `goal_radius` metres of it (clip_end, reaches_goal:
/// as Simulation::reach_goals judges arrival). Never with the rule off.
bool leaves_in_stride(const LeaveInStrideTuning& t, const MotionGraph& g, const Agent& a, const PlacedCandidate& c,
                      double goal_radius);

}  // namespace mobb::crowd
