#include "mobb/io/capsule.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

namespace mobb::io {

float capsule_radius(float bone_length) { return std::clamp(0.25f * bone_length, 0.01f, 0.06f); }

void add_capsule(CapsuleMesh& mesh, const glm::vec3& a, const glm::vec3& b, float radius) {
    const glm::vec3 d = b - a;
    const float len = glm::length(d);
    if (len < 1e-4f) return;
    const glm::vec3 axis = d / len;
    const glm::vec3 other = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(axis, other)), v = glm::cross(axis, u);
    const float rad = radius;
    // Rings along the axis: (offset from a, ring radius); the ends are rounded.
    const std::array<std::array<float, 2>, 6> rings = {
        {{-rad, 0}, {-0.7f * rad, 0.7f * rad}, {0, rad}, {len, rad}, {len + 0.7f * rad, 0.7f * rad}, {len + rad, 0}}};
    constexpr int kSides = 8;
    const auto base = std::uint32_t(mesh.positions.size());
    for (const auto& ring : rings) {
        for (int k = 0; k < kSides; ++k) {
            const float ang = 6.2831853f * float(k) / kSides;
            const glm::vec3 radial = std::cos(ang) * u + std::sin(ang) * v;
            mesh.positions.push_back(a + ring[0] * axis + ring[1] * radial);
            const glm::vec3 n = ring[1] * radial + (ring[0] < 0     ? ring[0]
                                                    : ring[0] > len ? ring[0] - len
                                                                    : 0.0f) *
                                                       axis;
            mesh.normals.push_back(glm::length(n) > 0 ? glm::normalize(n) : axis);
            mesh.along.push_back(std::clamp(ring[0] / len, 0.0f, 1.0f));
        }
    }
    for (std::uint32_t r = 0; r + 1 < rings.size(); ++r)
        for (std::uint32_t k = 0; k < kSides; ++k) {
            const std::uint32_t k1 = (k + 1) % kSides;
            const std::uint32_t a0 = base + r * kSides + k, a1 = base + r * kSides + k1;
            const std::uint32_t b0 = a0 + kSides, b1 = a1 + kSides;
            if (rings[r][1] > 0) mesh.indices.insert(mesh.indices.end(), {a0, b0, a1});
            if (rings[r + 1][1] > 0) mesh.indices.insert(mesh.indices.end(), {a1, b0, b1});
        }
}

}  // namespace mobb::io
