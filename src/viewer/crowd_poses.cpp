#include "crowd_poses.h"

#include <cmath>

namespace mobb::viewer {

std::vector<int> drawn_bones(const crowd::Rig& rig) {
    std::vector<int> out = rig.parents;
    for (int& p : out)
        if (p == 0) p = -1;
    return out;
}

std::vector<render::PosedSkeleton> crowd_skeletons(crowd::CrowdPoser& poser, const std::vector<int>& bones, double t,
                                                   const std::vector<glm::vec3>& colors) {
    std::vector<render::PosedSkeleton> out;
    const crowd::Record& r = poser.record();
    if (!(r.dt > 0)) return out;
    // The record's frame k covers [k dt, (k + 1) dt): the disk drawn at the cursor.
    const double k = std::floor(t / r.dt + 1e-9);
    if (!(k >= 0 && k < double(r.frames))) return out;
    for (int a = 0; a < int(r.tracks.size()); ++a) {
        render::PosedSkeleton p;
        if (!poser.pose(a, std::int64_t(k), p.joints)) continue;
        p.parents = &bones;
        // Darker than the agent's stack (the renderer darkens it once more): the skeleton stands on it.
        p.color = 0.6f * (std::size_t(a) < colors.size() ? colors[std::size_t(a)] : render::clip_color(a));
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace mobb::viewer
