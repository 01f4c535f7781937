// A capsule around a bone: the simple body of a skeleton, shared by the glTF export's skinned bodies and
// the viewer's capsule bodies, so both show the same person. Units: metres (any consistent unit).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace mobb::io {

/// Triangles of capsules: per vertex its position, unit normal and how far along its bone it lies (0 at
/// the first joint's end, 1 at the second's: the glTF export's skin weights).
struct CapsuleMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<float> along;
    std::vector<std::uint32_t> indices;  ///< three per triangle, counter-clockwise from outside
};

/// A bone's capsule radius: a quarter of its length, within 1 to 6 cm (fingers thin, limbs and trunk
/// about a limb's thickness; a simple stand-in, not a body model).
float capsule_radius(float bone_length);

/// Appends the capsule of radius `radius` around segment a-b: 8 sides, rounded ends. Nothing for a bone
/// shorter than 0.1 mm.
void add_capsule(CapsuleMesh& mesh, const glm::vec3& a, const glm::vec3& b, float radius);

}  // namespace mobb::io
