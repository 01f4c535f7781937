// The smallest disk holding a set of points on the ground: a character's tightest vertical cylinder
// at one sample (the paper's section 3 centres it on the root instead; `io::PathCentre`).
#pragma once
#include <vector>

#include <glm/vec2.hpp>

#include "mobb/core/path.h"

namespace mobb {

/// The smallest disk (centre x, y and radius r, metres) containing every point, by Welzl's algorithm
/// ("Smallest enclosing disks (balls and ellipsoids)", 1991) in its iterative move-to-front form, points
/// taken in the order given: deterministic, O(n^3) at worst, near linear in practice for a skeleton's
/// joints. r is then raised to the largest distance from the centre, so every point lies within r exactly
/// as computed. No points give {0, 0, 0}; finite points are a precondition.
Sample enclosing_disk(const std::vector<glm::dvec2>& points);

}  // namespace mobb
