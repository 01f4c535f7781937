// Benchmark workloads shared by the micro-benchmarks and the callgrind driver: long real sequences
// (CMU clips' paths joined end to end) and random placements. Benchmarks only, never the core.
#pragma once
#include <string>
#include <vector>

#include "mobb/core/path.h"

namespace mobb::bench {

/// Paths joined end to end: each part translated so its first sample sits on the previous part's
/// last sample, then cut to `seconds`. All parts share the first part's dt.
Path concatenate(const std::vector<Path>& parts, double seconds);

/// A ~42 s real sequence at `fps` Hz: 0 = 001_01 + 001_08, 1 = 001_14 + 002_05 + 005_02 (CMU).
/// Falls back to a random walk of the same length when the mocap folder is absent (see `source`).
const Path& sequence42(int which, double fps);

/// Where sequence42 came from: "cmu" or "random walk".
std::string source();

/// Placement pairs for A and B: A at the origin, B with random translation in [-4, 4] m on each
/// axis, rotation in [0, 2 pi) and time offset in [-d/2, d/2] for a clip duration d (as the existing
/// micro-benchmarks and the paper's Table 2 setup). Deterministic for a seed.
struct Placements {
    std::vector<Placement> a, b;
};
Placements random_placements(double duration, std::size_t count, unsigned seed);

}  // namespace mobb::bench
