// Skeletons of a recorded crowd at the time cursor: the agents' poses come from the library's one home
// for them (mobb/crowd/agent_pose.h: sources, localisation, placement); this draws the frame at the cursor.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "frame.h"
#include "mobb/crowd/agent_pose.h"
#include "mobb/crowd/motion_graph.h"
#include "mobb/crowd/record.h"

namespace mobb::viewer {

using crowd::PoseSource;
using crowd::PoseSources;

/// The skeleton of every agent at time t (agents whose source failed are left out), coloured per agent.
std::vector<render::PosedSkeleton> crowd_skeletons(const crowd::Record& record, const crowd::MotionGraph& graph,
                                                   PoseSources& sources, double t,
                                                   const std::vector<glm::vec3>& agent_colors);

}  // namespace mobb::viewer
