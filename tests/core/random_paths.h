// Synthetic paths for core tests: random walks with varying speed, heading and radius.
#pragma once
#include <cmath>
#include <random>

#include "mobb/core/path.h"

namespace mobb::test {

inline Path random_walk(std::mt19937_64& rng, int n, double dt = 1.0 / 60.0, double speed = 1.3) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Path p;
    p.dt = dt;
    double x = 0, y = 0, heading = u(rng) * 6.283185307179586, turn = 0;
    const double r0 = 0.2 + 0.4 * u(rng);
    for (int i = 0; i < n; ++i) {
        turn = 0.95 * turn + 0.3 * (u(rng) - 0.5);
        heading += turn * dt * 4;
        const double v = speed * (0.5 + u(rng));
        x += v * dt * std::cos(heading);
        y += v * dt * std::sin(heading);
        p.samples.push_back({x, y, r0 * (0.7 + 0.6 * u(rng))});
    }
    return p;
}

inline Path standing_still(int n, double r = 0.3) {
    Path p;
    for (int i = 0; i < n; ++i) p.samples.push_back({1.0, -2.0, r});
    return p;
}

// A closed circle: first and last sample coincide.
inline Path circle(int n, double radius = 2.0, double r = 0.3) {
    Path p;
    for (int i = 0; i < n; ++i) {
        const double a = 6.283185307179586 * i / (n - 1);
        p.samples.push_back({radius * std::cos(a), radius * std::sin(a), r});
    }
    return p;
}

}  // namespace mobb::test
