// A small seeded generator with fixed arithmetic (the standard distributions differ between libraries),
// so a seed gives the same crowd everywhere.
#pragma once
#include <cstdint>

namespace mobb::util {

class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}

    /// The stream of one crowd choice point, a function of (seed, agent, frame) only: the draws of a
    /// choice point do not depend on which choice points ran before it or on which thread.
    static Random stream(std::uint64_t seed, std::uint64_t agent, std::uint64_t frame) {
        return Random(mix(mix(mix(seed) ^ agent) ^ frame));
    }

    std::uint64_t next() { return mix(state_ += 0x9e3779b97f4a7c15ull); }  // SplitMix64
    /// Uniform in [0, 1).
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform integer in [0, n), n > 0.
    int below(int n) { return int(uniform() * double(n)); }

private:
    // SplitMix64's finaliser: a bijection that spreads every input bit over the output.
    static std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }

    std::uint64_t state_;
};

}  // namespace mobb::util
