// Space-time (x, y, t) and the GL world: x stays x, time goes up (t * time_scale metres per second)
// and the ground's y becomes -z, which keeps both frames right-handed.
#pragma once
#include <array>

#include <glm/vec3.hpp>

#include "mobb/core/obb.h"
#include "mobb/core/path.h"

namespace mobb::render {

inline glm::vec3 to_gl(double x, double y, double t, double time_scale) {
    return {float(x), float(t * time_scale), float(-y)};
}

/// Corners of a space-time box in the GL world; corner k has bit i set for +half[i].
std::array<glm::vec3, 8> corners(const Obb3& box, double time_scale);

/// The 12 edges and 6 faces (as 4 corner indices, outward) of a box, over corners().
extern const int kBoxEdges[12][2];
extern const int kBoxFaces[6][4];

/// Axis-aligned bounds in space-time (metres, metres, seconds).
struct Bounds {
    glm::dvec3 lo{0.0}, hi{0.0};
    bool empty = true;

    void add(const glm::dvec3& p);
};

}  // namespace mobb::render
