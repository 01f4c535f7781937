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

std::vector<double> sample_speeds(const Path& path) {
    const std::size_t n = path.size();
    std::vector<double> out(n, 0.0);
    if (n < 2) return out;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = i > 0 ? i - 1 : 0, b = i + 1 < n ? i + 1 : n - 1;
        const Sample &p = path.samples[a], &q = path.samples[b];
        out[i] = std::hypot(q.x - p.x, q.y - p.y) / (double(b - a) * path.dt);
    }
    return out;
}

}  // namespace mobb
