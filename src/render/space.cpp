#include "space.h"

#include <algorithm>
#include <cmath>

namespace mobb::render {

std::array<glm::vec3, 8> corners(const Obb3& box, double time_scale) {
    std::array<glm::vec3, 8> out;
    for (int k = 0; k < 8; ++k) {
        glm::dvec3 p = box.center;
        for (int i = 0; i < 3; ++i) p += box.axes[i] * (((k >> i) & 1) ? box.half[i] : -box.half[i]);
        out[std::size_t(k)] = to_gl(p.x, p.y, p.z, time_scale);
    }
    return out;
}

const int kBoxEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                              {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
const int kBoxFaces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};

void Bounds::add(const glm::dvec3& p) {
    if (empty) {
        lo = hi = p;
        empty = false;
        return;
    }
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

}  // namespace mobb::render
