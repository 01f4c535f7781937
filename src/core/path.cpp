#include "mobb/core/path.h"

#include <stdexcept>
#include <string>

namespace mobb {

void validate(const Path& path) {
    if (!(std::isfinite(path.dt) && path.dt > 0))
        throw std::invalid_argument("path: sample spacing dt must be positive and finite");
    for (std::size_t i = 0; i < path.samples.size(); ++i) {
        const Sample& s = path.samples[i];
        if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.r) || s.r < 0)
            throw std::invalid_argument("path: sample " + std::to_string(i) + " is not finite or has r < 0");
    }
}

}  // namespace mobb
