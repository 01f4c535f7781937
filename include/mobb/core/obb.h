// Oriented boxes in the plane and in space-time (x, y, t), and their separating-axis tests.
#pragma once
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mobb/core/path.h"

namespace mobb {

/// 2D oriented box: centre, unit major axis u (minor axis v = (-u.y, u.x)), half extents along u and v.
/// Metres.
struct Obb2 {
    glm::dvec2 center{0.0};
    glm::dvec2 axis{1.0, 0.0};
    glm::dvec2 half{0.0};

    glm::dvec2 minor() const { return {-axis.y, axis.x}; }
    double area() const { return 4.0 * half.x * half.y; }
};

/// 3D oriented box in space-time (x, y, t): centre, orthonormal right-handed axes (columns), half
/// extents along each axis. Metres and seconds share one Euclidean metric; SAT is exact in any units.
struct Obb3 {
    glm::dvec3 center{0.0};
    glm::dmat3 axes{1.0};
    glm::dvec3 half{0.0};

    double volume() const { return 8.0 * half.x * half.y * half.z; }
};

/// A 2D box extruded over [t_min, t_max] (seconds) as a 3D space-time box.
Obb3 extrude(const Obb2& box, double t_min, double t_max);

Obb2 transformed(const Obb2& box, const SpaceTimeRigid& m);
Obb3 transformed(const Obb3& box, const SpaceTimeRigid& m);

/// Separating-axis test of two 2D boxes in one frame: 4 candidate axes (Gottschalk et al. 1996).
/// True when no axis separates them (they overlap or touch).
bool overlap(const Obb2& a, const Obb2& b);

/// Separating-axis test of two 3D boxes in one frame: 15 candidate axes (3 + 3 face normals, 9 edge
/// cross products), with a small guard for near-parallel edges. True when they overlap or touch.
bool overlap(const Obb3& a, const Obb3& b);

}  // namespace mobb
