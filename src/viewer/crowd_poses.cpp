#include "crowd_poses.h"

#include <cmath>

namespace mobb::viewer {

std::vector<render::PosedSkeleton> crowd_skeletons(const crowd::Record& r, const crowd::MotionGraph& g,
                                                   PoseSources& sources, double t,
                                                   const std::vector<glm::vec3>& colors) {
    std::vector<render::PosedSkeleton> out;
    if (!(r.dt > 0)) return out;
    // The record's frame k covers [k dt, (k + 1) dt): the disk drawn at the cursor.
    const double k = std::floor(t / r.dt + 1e-9);
    if (!(k >= 0 && k < double(r.frames))) return out;
    for (int a = 0; a < int(r.tracks.size()); ++a) {
        crowd::AgentClipAt at;
        if (!crowd::agent_clip_at(r, g, a, std::int64_t(k), at)) continue;
        const crowd::GraphClip& gc = g.clips[std::size_t(at.placed->clip)];
        const PoseSource& src = sources.get(gc.source);
        if (!src.clip || at.sample >= src.clip->animation.frames()) continue;
        render::PosedSkeleton p;
        p.animation = &src.clip->animation;
        p.up = src.clip->up;
        p.frame = at.sample;
        p.place = crowd::source_to_world(src, gc, at.placed->place);
        p.floor = src.floor;
        // Darker than the agent's stack (the renderer darkens it once more): the skeleton stands on it.
        p.color = 0.6f * (std::size_t(a) < colors.size() ? colors[std::size_t(a)] : render::clip_color(a));
        out.push_back(p);
    }
    return out;
}

}  // namespace mobb::viewer
