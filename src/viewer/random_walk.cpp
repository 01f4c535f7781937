#include "random_walk.h"

#include <cmath>
#include <cstdint>

#include "mobb/core/angle.h"

namespace mobb::viewer {

namespace {

/// splitmix64: portable, unlike std:: distributions whose output differs between libraries.
struct Random {
    std::uint64_t state;
    double uniform() {  // [0, 1)
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }
};

}  // namespace

Path random_walk(const RandomWalk& walk) {
    Random rng{walk.seed * 7919ULL + 17};
    Path path;
    path.dt = 1.0 / walk.hz;
    const auto n = std::size_t(std::llround(walk.seconds * walk.hz));
    double x = 0, y = 0, heading = rng.uniform() * 6.283185307179586, turn = 0;
    const double phase = rng.uniform() * 6.283185307179586;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) * path.dt;
        turn = 0.98 * turn + 0.02 * (rng.uniform() - 0.5) * 4.0;
        // Steer back toward the origin when far away, so crowds stay on their own plot.
        const double home = std::atan2(-y, -x), dist = std::hypot(x, y);
        const double err = wrap_angle(home - heading);
        heading += (turn + (dist > 4.0 ? 0.8 * err : 0.0)) * path.dt;
        x += 1.3 * std::cos(heading) * path.dt;
        y += 1.3 * std::sin(heading) * path.dt;
        path.samples.push_back({x, y, 0.35 + 0.1 * std::sin(6.0 * t + phase)});
    }
    return path;
}

}  // namespace mobb::viewer
