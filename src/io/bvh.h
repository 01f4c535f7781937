// BVH (Biovision hierarchy) reader: text -> joints and channel values -> forward kinematics.
// Internal to mobb_io; the tests and the fuzzer use it directly.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "mobb/io/animation.h"

namespace mobb::io::bvh {

enum class Channel : std::uint8_t { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

struct Joint {
    std::string name;
    int parent = -1;  ///< index into Document::joints, -1 for the root
    bool end_site = false;
    glm::dvec3 offset{0.0};         ///< file units
    std::vector<Channel> channels;  ///< in the order the file lists them (0..6, no repeats)
    int first_value = 0;            ///< index of this joint's first channel within a frame
    int line = 0;                   ///< where the joint is declared
};

/// A parsed file. Joints are in file order, so every parent precedes its children.
struct Document {
    std::vector<Joint> joints;
    int channels = 0;            ///< values per frame (>= 1)
    int frames = 0;              ///< >= 1
    double frame_time = 0;       ///< seconds, as written (> 0)
    std::vector<double> values;  ///< frames * channels, frame-major; degrees and file units
};

/// Limits that keep hostile input from costing absurd memory or time (see also detail::kMaxPositions).
inline constexpr int kMaxDepth = 1000;        ///< joints nested inside each other
inline constexpr int kMaxJoints = 100000;     ///< including End Sites
inline constexpr double kMaxMagnitude = 1e9;  ///< largest |number| accepted anywhere

/// Parses a whole BVH text. `file` only names the source in errors.
/// Throws LoadError "FILE:LINE: message" (LINE 1-based, of the offending token).
/// Frames must be one per line with exactly `channels` numbers each; every number must be finite
/// with magnitude <= kMaxMagnitude; Frame Time > 0; nothing but blanks may follow the last frame.
Document parse(std::string_view text, const std::string& file);

/// Forward kinematics of every frame: world = parent_world * translate(offset + position channels)
/// * R(ch1) * R(ch2) * R(ch3) (rotation channels in the order listed, degrees). Positions are
/// multiplied by `scale` (metres per file unit). dt is the Frame Time, snapped to 1/N s when the
/// file's value is a rounded 1/N (0.016667 -> 1/60), so resampling and durations come out exact.
Animation animate(const Document& doc, double scale);

}  // namespace mobb::io::bvh
