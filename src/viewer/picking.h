// Clicking a disk: the first sample cylinder a camera ray enters, and the ground point under a ray.
#pragma once
#include <optional>

#include "camera.h"
#include "panels.h"
#include "state.h"

namespace mobb::viewer {

/// The nearest visible disk hit by the ray (GL world), or an empty pick.
Pick pick_disk(const State& state, const render::Ray& ray);

/// Where the ray meets the horizontal plane at GL height `height` (0 = the ground), as ground (x, y).
std::optional<glm::dvec2> ground_point(const render::Ray& ray, double height = 0.0);

}  // namespace mobb::viewer
