// Clicking a disk: the first sample cylinder a camera ray enters, and the ground point under a ray.
#pragma once
#include <optional>

#include "camera.h"
#include "panels.h"
#include "state.h"

namespace mobb::viewer {

/// The nearest visible disk hit by the ray (GL world), or an empty pick; `distance` receives the ray
/// parameter of the hit (infinity for none).
Pick pick_disk(const State& state, const render::Ray& ray, double* distance = nullptr);

/// A box of the query's clip A or B as drawn (the boxes layer's level or all levels).
struct BoxPick {
    int clip = -1;
    std::int32_t node = -1;
    double distance = 0;  ///< ray parameter where the ray enters it
};

/// The nearest drawn box of the query's clips that the ray enters (slab test in the box's frame), or
/// an empty pick when the boxes layer is off or no box is hit.
BoxPick pick_box(const State& state, const render::Ray& ray);

/// A picked disk where it stands: centre on the ground (m), its sample's time interval (s), radius (m).
struct DiskInfo {
    glm::dvec2 centre{0.0};
    double t0 = 0, t1 = 0, r = 0;
};
std::optional<DiskInfo> disk_of(const State& state, const Pick& pick);

/// From one picked disk to another: distance between centres (m), time between the samples' intervals
/// (s, 0 when they overlap), r_a + r_b (m), and distance - (r_a + r_b).
struct Ruler {
    double distance = 0, time_gap = 0, radii = 0, clearance = 0;
};
std::optional<Ruler> measure(const State& state, const Pick& a, const Pick& b);

/// Where the ray meets the horizontal plane at GL height `height` (0 = the ground), as ground (x, y).
std::optional<glm::dvec2> ground_point(const render::Ray& ray, double height = 0.0);

}  // namespace mobb::viewer
