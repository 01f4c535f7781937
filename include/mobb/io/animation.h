// Skeleton animation: joint positions per frame, and the path derived from it (paper section 3).
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mobb/core/path.h"

namespace mobb::io {

enum class UpAxis { Y, Z };

/// A joint hierarchy. End Sites (BVH) are joints too, flagged, so r counts them.
struct Skeleton {
    std::vector<std::string> names;
    std::vector<int> parents;  ///< -1 for the root
    std::vector<bool> end_site;
    int root = 0;

    int size() const { return int(names.size()); }
};

/// World positions of every joint at every frame, in the file's own axes, already scaled to metres.
struct Animation {
    Skeleton skeleton;
    double dt = 1.0 / 60.0;             ///< seconds between frames
    std::vector<glm::dvec3> positions;  ///< frame-major: positions[f * joints + j]

    int frames() const { return skeleton.size() ? int(positions.size()) / skeleton.size() : 0; }
    const glm::dvec3& at(int frame, int joint) const { return positions[std::size_t(frame) * skeleton.size() + joint]; }
};

/// Ground plane and height of a point: Y-up (x, y, h) = (X, -Z, Y); Z-up (x, y, h) = (X, Y, Z).
/// Keeps (x, y, t) right-handed with positive angles counter-clockwise seen from above.
glm::dvec3 to_ground(const glm::dvec3& p, UpAxis up);

/// Where a path's disks are centred.
enum class PathCentre {
    Root,       ///< the root projected onto the ground (the paper's section 3)
    Enclosing,  ///< the centre of the smallest disk holding every projected joint (enclosing_disk): on the
                ///< committed graph's takes 16 % narrower on average, the centre up to 0.35 m off the root
};

/// Path of an animation: p_i = the sample's centre (`centre`), r_i = largest ground distance from p_i
/// to any projected joint (End Sites included). dt = animation dt.
Path path_of(const Animation& anim, UpAxis up, PathCentre centre = PathCentre::Root);

}  // namespace mobb::io
