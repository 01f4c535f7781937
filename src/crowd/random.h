// A small seeded generator with fixed arithmetic (the standard distributions differ between libraries),
// so a seed gives the same crowd everywhere.
#pragma once
#include <cstdint>

namespace mobb::crowd {

class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {  // SplitMix64
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1).
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform integer in [0, n), n > 0.
    int below(int n) { return int(uniform() * double(n)); }

private:
    std::uint64_t state_;
};

}  // namespace mobb::crowd
