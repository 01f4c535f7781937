// Small helpers shared by the readers. Internal to mobb_io.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace mobb::io::detail {

/// Budgets that keep hostile input (or options) from costing absurd memory: joint positions held by
/// one animation (frames * joints, 24 bytes each), and samples of one animation.
inline constexpr std::int64_t kMaxPositions = std::int64_t(1) << 27;
inline constexpr double kMaxSamples = 1e7;

/// A frame time snapped to 1/N s when it is a rounded 1/N (within 1e-4 relative): BVH writers print
/// 0.016667 for 1/60 and glTF stores key times as float32. Other values are returned unchanged.
double snap_dt(double dt);

/// Text safe to quote in a one-line error: at most `max` characters, control bytes replaced by '?'.
std::string quote(std::string_view text, std::size_t max = 40);

}  // namespace mobb::io::detail
