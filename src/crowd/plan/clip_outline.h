// A graph clip's outline (its roots' convex hull) and a candidate clip placed in the world: its space-time
// box and how far it leaves the world, from the hull's vertices rather than every sample. Private to
// src/crowd.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/crowd/collision/broad_phase.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/world/world.h"

namespace mobb::crowd {

/// A clip's root positions reduced to their convex hull (clip frame, metres, counter-clockwise) and its
/// largest radius. A placed clip's world box and how far it leaves the world are maxima of convex
/// functions of the root position, so the hull's vertices give them: a few points instead of every sample.
struct ClipOutline {
    std::vector<std::array<double, 2>> hull;
    double r_max = 0;
    /// Per kBlock samples in order, a circle (x, y, radius) holding their disks: held ground far from
    /// one skips its samples.
    std::vector<std::array<double, 3>> blocks;
    static constexpr std::size_t kBlock = 8;
    /// Per direction bin (kBins over the turn, bin b around the angle 2 pi (b + 0.5) / kBins), the hull
    /// vertex farthest that way: where place_clip starts its walk to each side of a placed box.
    std::vector<int> extreme;
    static constexpr int kBins = 64;  // a power of two
};
ClipOutline outline_of(const Path& path);
std::vector<ClipOutline> outlines_of(const MotionGraph& g);

/// A candidate clip placed in the world: its space-time box and how far it leaves the world.
struct PlacedCandidate {
    int clip = 0;
    Placement place;
    SpaceTimeBox box;
    bool leaves_world = false;  ///< excess > 0 (Candidate::leaves_world)
    double excess = 0;          ///< metres farther outside than at the start (the random mode's "leaves the world")
};

/// Places graph clip `clip` (outline `outline`, `frames` long) at `p` (rotation m = Rigid2::of(p)) from
/// global frame `frame` on. The box pads the hull by r_max, so it holds every sample disk. With a world,
/// also how far the clip leaves its rectangle.
PlacedCandidate place_clip(const ClipOutline& outline, int clip, std::int64_t frames, const Placement& p,
                           const Rigid2& m, std::int64_t frame, const World* world);

}  // namespace mobb::crowd
