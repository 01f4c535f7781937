#include "crowd_poses.h"

#include <cmath>

namespace mobb::viewer {

std::vector<int> drawn_bones(const crowd::Rig& rig) {
    std::vector<int> out = rig.parents;
    for (int& p : out)
        if (p == 0) p = -1;
    return out;
}

namespace {

/// A small square on the ground at time t under a planted point.
render::Prism planted_mark(const glm::dvec3& at, double t) {
    constexpr double kHalf = 0.05;  // metres: a mark a foot's width, under the stacks' disks
    return {{{at.x - kHalf, at.y - kHalf},
             {at.x + kHalf, at.y - kHalf},
             {at.x + kHalf, at.y + kHalf},
             {at.x - kHalf, at.y + kHalf}},
            t,
            t,
            glm::vec3(0.1f),
            0,
            true};
}

void add_planted(const crowd::CrowdPoser& poser, const crowd::FeetAt& feet, const std::vector<glm::dvec3>& joints,
                 double t, std::vector<render::Prism>& out) {
    for (std::size_t f = 0; f < 2; ++f) {
        if (feet.plant[f] == crowd::Plant::Free) continue;
        const crowd::RigLeg& leg = poser.legs()[f];
        const int joint = feet.plant[f] == crowd::Plant::Heel ? leg.ankle : leg.toe;
        if (joint >= 0 && std::size_t(joint) < joints.size())
            out.push_back(planted_mark(joints[std::size_t(joint)], t));
    }
}

}  // namespace

std::vector<render::PosedSkeleton> crowd_skeletons(crowd::CrowdPoser& poser, const std::vector<int>& bones, double t,
                                                   const std::vector<glm::vec3>& colors,
                                                   std::vector<render::Prism>* planted) {
    std::vector<render::PosedSkeleton> out;
    const crowd::Record& r = poser.record();
    if (!(r.dt > 0)) return out;
    // The record's frame k covers [k dt, (k + 1) dt): the disk drawn at the cursor.
    const double k = std::floor(t / r.dt + 1e-9);
    if (!(k >= 0 && k < double(r.frames))) return out;
    std::vector<glm::dvec3> raw, unlocked;
    crowd::FeetAt feet;
    for (int a = 0; a < int(r.tracks.size()); ++a) {
        render::PosedSkeleton p;
        if (!poser.pose(a, std::int64_t(k), p.joints, raw, unlocked, &feet)) continue;
        if (planted) add_planted(poser, feet, p.joints, t, *planted);
        p.parents = &bones;
        // Darker than the agent's stack (the renderer darkens it once more): the skeleton stands on it.
        p.color = 0.6f * (std::size_t(a) < colors.size() ? colors[std::size_t(a)] : render::clip_color(a));
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace mobb::viewer
