// Seeded random-walk paths: synthetic clips for data-free tests and the 360,000-disk benchmark.
#pragma once
#include "mobb/core/path.h"
#include "scene.h"

namespace mobb::viewer {

/// A walker at about 1.3 m/s turning smoothly and staying within ~4 m of the origin, with a radius
/// that swings like arms (0.25..0.45 m). Identical on every machine for a given seed.
Path random_walk(const RandomWalk& walk);

}  // namespace mobb::viewer
