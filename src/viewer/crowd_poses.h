// Skeletons of a recorded crowd at the time cursor: the agents' poses come from the library's one home
// for them (mobb/crowd/motion/agent_pose.h: sources, placement, blending at clip starts), as the export's and Python's.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "frame.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/motion/agent_pose.h"
#include "mobb/crowd/record/record.h"

namespace mobb::viewer {

using crowd::PoseSource;
using crowd::PoseSources;

/// The bones drawn: the rig's, less those to joint 0 (the root's ground point, not a point of the body).
std::vector<int> drawn_bones(const crowd::Rig& rig);

/// The skeleton of every agent at time t: its blended pose at the record frame the cursor is in (the
/// disk drawn there) with `bones` (drawn_bones, kept by the caller), coloured per agent. With `planted`,
/// a mark at the cursor under each planted foot (its contact's planted point: the ankle on the heel, the
/// toe on the toe alone; foot_contact.h) is appended to it.
std::vector<render::PosedSkeleton> crowd_skeletons(crowd::CrowdPoser& poser, const std::vector<int>& bones, double t,
                                                   const std::vector<glm::vec3>& agent_colors,
                                                   std::vector<render::Prism>* planted = nullptr);

}  // namespace mobb::viewer
