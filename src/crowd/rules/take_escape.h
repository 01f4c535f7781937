// Taking one's own escape (plan/escape.h): when no candidate's plan is free, the agent plays its next
// stopping clip - the others planned around it - or, at its held ground, one more idle clip inside it.
// Always on: it is what keeps the crowd free of contacts.
#pragma once
#include "plan/crowd_state.h"

namespace mobb::crowd {

/// The escape of the agent at `base`: the next clip of the plan it reserved (`out_clip`) and the rest of
/// that plan (`out_plan`); at its held ground, one more idle clip all of whose disks lie inside it (free:
/// the others planned around it), the smallest such successor, and the same ground. Returns whether it
/// has one; nothing is written otherwise.
bool take_escape(const CrowdState& s, const ChoiceBase& base, BoxedClip& out_clip, Plan& out_plan);

}  // namespace mobb::crowd
