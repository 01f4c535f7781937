// Image comparison with two tolerances, and what a failed comparison leaves behind for a human.
#pragma once
#include <string>

#include "image.h"

namespace mobb::test {

struct Tolerance {
    int channel = 8;          ///< largest per-channel difference (0..255) still counted as equal
    double fraction = 0.002;  ///< largest fraction of pixels allowed to differ
    /// Hard per-pixel limit: no channel of any pixel may differ by more, however few pixels differ (a
    /// rasteriser moving an edge by a pixel blends; a missing label, box edge or tick does not).
    int hard = 200;
};

struct Diff {
    bool same_size = false;
    long differing = 0;     ///< pixels with some channel differing by more than the tolerance
    double fraction = 1.0;  ///< differing / pixels
    int largest = 0;        ///< largest channel difference seen
    render::Image image;    ///< differing pixels in red, the rest as a faded copy of `expected`

    bool matches(const Tolerance& t) const { return same_size && fraction <= t.fraction && largest <= t.hard; }
};

Diff compare(const render::Image& expected, const render::Image& actual, const Tolerance& tolerance);

/// Writes DIR/NAME.expected.png, .actual.png and .diff.png; returns DIR/NAME.
std::string write_failure(const std::string& dir, const std::string& name, const render::Image& expected,
                          const render::Image& actual, const Diff& diff);

}  // namespace mobb::test
