// Colour maps for per-sample and per-box quantities, and the scale a colour bar shows. Two
// perceptually uniform maps: viridis (sequential; van der Walt and Smith, matplotlib 1.5, CC0) and
// Moreland's cool-warm (diverging, "Diverging Color Maps for Scientific Visualization", ISVC 2009),
// each as 33 entries sampled from matplotlib (scripts/colour_tables.py) and interpolated linearly.
#pragma once
#include <array>
#include <cstdint>
#include <string>

#include <glm/vec3.hpp>

namespace mobb::render {

enum class ColourMap : std::uint8_t {
    Viridis,    ///< sequential: dark blue (low) to yellow (high)
    Diverging,  ///< blue (low) through light grey (the middle of the scale) to red (high)
};

constexpr int kColourMapEntries = 33;
/// The map's table, evenly spaced over [0, 1].
const std::array<glm::vec3, kColourMapEntries>& colour_table(ColourMap map);
/// The map at u in [0, 1] (clamped; NaN reads as 0).
glm::vec3 colour_at(ColourMap map, double u);

/// A quantity's range on a map, and what the colour bar prints: "label (unit)".
struct ColourScale {
    ColourMap map = ColourMap::Viridis;
    double lo = 0, hi = 1;  ///< values at the map's start and end (lo > hi reverses it); beyond, the end colours
    std::string label, unit;
    double least() const { return lo < hi ? lo : hi; }
    double most() const { return lo < hi ? hi : lo; }
    /// Where `value` falls on the map, 0..1 (0.5 when lo == hi).
    double position(double value) const;
    glm::vec3 colour(double value) const { return colour_at(map, position(value)); }
};

}  // namespace mobb::render
