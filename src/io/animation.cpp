#include "mobb/io/animation.h"

#include <algorithm>
#include <cmath>

namespace mobb::io {

glm::dvec3 to_ground(const glm::dvec3& p, UpAxis up) { return up == UpAxis::Y ? glm::dvec3(p.x, -p.z, p.y) : p; }

Path path_of(const Animation& anim, UpAxis up) {
    Path path;
    path.dt = anim.dt;
    const int joints = anim.skeleton.size();
    const int frames = anim.frames();
    path.samples.reserve(std::size_t(frames));
    for (int f = 0; f < frames; ++f) {
        const glm::dvec3 root = to_ground(anim.at(f, anim.skeleton.root), up);
        double r = 0;
        for (int j = 0; j < joints; ++j) {
            const glm::dvec3 g = to_ground(anim.at(f, j), up);
            r = std::max(r, std::hypot(g.x - root.x, g.y - root.y));
        }
        path.samples.push_back({root.x, root.y, r});
    }
    return path;
}

}  // namespace mobb::io
