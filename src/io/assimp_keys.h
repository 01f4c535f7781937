// One Assimp animation channel as key lists in seconds, and its local transform at any time.
// Internal to mobb_io.
#pragma once
#include <string>
#include <vector>

#include <assimp/anim.h>
#include <assimp/matrix4x4.h>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace mobb::io::assimp {

template <typename Value>
struct Keys {
    std::vector<double> times;  ///< seconds, non-decreasing
    std::vector<Value> values;

    bool changes() const;
    /// Linear (slerp for rotations) between the keys around `time`, clamped to the first and last key.
    Value at(double time) const;
};

struct Track {
    int node = -1;
    Keys<glm::dvec3> translation;
    Keys<glm::dquat> rotation;
    Keys<glm::dvec3> scale;

    /// True when some key differs from the others (a channel Blender bakes for a still object does not move).
    bool moves() const { return translation.changes() || rotation.changes() || scale.changes(); }
    /// The node's local matrix at `time`: components without keys keep their value in `rest`.
    glm::dmat4 at(double time, const aiMatrix4x4& rest) const;
};

/// Reads a channel, key times divided by `tps` (ticks per second). Throws LoadError "WHERE: message" for
/// non-finite values or times, times that decrease and zero quaternions.
Track read_track(const aiNodeAnim& channel, double tps, const std::string& where);

}  // namespace mobb::io::assimp
