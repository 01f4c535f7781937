#include "mobb/io/animation.h"

#include <algorithm>
#include <cmath>

#include "mobb/core/enclosing_disk.h"

namespace mobb::io {

glm::dvec3 to_ground(const glm::dvec3& p, UpAxis up) { return up == UpAxis::Y ? glm::dvec3(p.x, -p.z, p.y) : p; }

namespace {

Sample root_centred(const Animation& anim, UpAxis up, int f) {
    const glm::dvec3 root = to_ground(anim.at(f, anim.skeleton.root), up);
    double r = 0;
    for (int j = 0; j < anim.skeleton.size(); ++j) {
        const glm::dvec3 g = to_ground(anim.at(f, j), up);
        r = std::max(r, std::hypot(g.x - root.x, g.y - root.y));
    }
    return {root.x, root.y, r};
}

Sample enclosing(const Animation& anim, UpAxis up, int f, std::vector<glm::dvec2>& ground) {
    ground.clear();
    for (int j = 0; j < anim.skeleton.size(); ++j) {
        const glm::dvec3 g = to_ground(anim.at(f, j), up);
        ground.emplace_back(g.x, g.y);
    }
    return enclosing_disk(ground);
}

}  // namespace

Path path_of(const Animation& anim, UpAxis up, PathCentre centre) {
    Path path;
    path.dt = anim.dt;
    const int frames = anim.frames();
    path.samples.reserve(std::size_t(frames));
    std::vector<glm::dvec2> ground;
    for (int f = 0; f < frames; ++f)
        path.samples.push_back(centre == PathCentre::Root ? root_centred(anim, up, f) : enclosing(anim, up, f, ground));
    return path;
}

}  // namespace mobb::io
