// How far a clip's root gets from where it starts: what tells an idle or in-place clip from a walk
// (kind_of) and which clips the graph build snaps to stand still.
#pragma once
#include "mobb/core/path.h"

namespace mobb::crowd {

/// The largest ground distance of a sample's root from the first sample's (metres).
double reach_of(const Path& path);

}  // namespace mobb::crowd
