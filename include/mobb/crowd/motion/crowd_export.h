// A crowd record as animated skeletons for other tools (`mobb export-crowd`): the agents' poses
// (agent_pose.h, blended at clip starts) on a frame grid, and the world's walls, obstacles and goals.
#pragma once
#include <optional>
#include <stdexcept>

#include "mobb/crowd/motion/agent_pose.h"
#include "mobb/io/export.h"

namespace mobb::crowd {

struct CrowdExportOptions {
    int agent_begin = 0;
    std::optional<int> agent_end;  ///< agents [begin, end); none: to the last
    double t_begin = 0;
    std::optional<double> t_end;  ///< seconds; none: the record's last frame, (frames - 1) dt
    double fps = 0;               ///< frames per second written; 0: the record's (1 / dt)
    bool bodies = false;          ///< a capsule per bone (io::ExportScene::bodies)
    bool world = true;            ///< walls, obstacles and goals as shapes
};

/// Frames written: at t_begin + f / fps for f = 0 .. while <= t_end (+1e-9 s). Throws std::invalid_argument
/// (one line naming the option) for an agent range outside 0 <= begin < end <= agents, times outside
/// 0 <= t_begin <= t_end <= (frames - 1) dt, or fps outside (0, 1000].
io::ExportScene crowd_scene(CrowdPoser& poser, const CrowdExportOptions& options);

}  // namespace mobb::crowd
