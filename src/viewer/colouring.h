// The values behind the disk and box colourings (frame.h DiskColour, BoxColour): per sample of each
// clip (radius, speed, time, clearance to the nearest other clip) and per node of each tree
// (tightness, tests by the shown query), with the ranges their colour bars show. Computed through
// core's plain functions when first drawn and kept until the clips, the colourings or the query change.
#pragma once
#include <cstdint>
#include <vector>

#include "frame.h"

namespace mobb::viewer {

struct State;

/// Clearances beyond this many metres either side of 0 show the diverging map's end colours.
constexpr double kClearanceRange = 1.0;

struct Colouring {
    struct Key {
        std::uint64_t revision = 0;
        render::DiskColour disks = render::DiskColour::Clip;
        render::BoxColour boxes = render::BoxColour::Level;
        int level = 0, levels = 1;
        bool all_levels = false;
        const void* trace = nullptr;
        std::size_t trace_size = 0;
        int query_a = -1, query_b = -1;
        bool operator==(const Key& o) const {
            return revision == o.revision && disks == o.disks && boxes == o.boxes && level == o.level &&
                   levels == o.levels && all_levels == o.all_levels && trace == o.trace && trace_size == o.trace_size &&
                   query_a == o.query_a && query_b == o.query_b;
        }
    };
    Key key;
    bool valid = false;
    std::vector<std::vector<float>> samples;  ///< [clip][sample]; empty for DiskColour::Clip
    std::vector<std::vector<float>> nodes;    ///< [clip][node]; empty for BoxColour::Level
    render::ColourScale disk_scale, box_scale;
    std::uint64_t serial = 0;  ///< bumped whenever the values change (the frame's colour_revision)
};

/// Brings the colouring up to date with the state (recomputing only what its key says changed).
void update_colouring(const State& s, Colouring& c);

/// The per-sample values of one colouring for every clip of the state (empty vectors for Clip).
std::vector<std::vector<float>> sample_values(const State& s, render::DiskColour colour);
/// The per-node values of one box colouring for every clip's tree (empty vectors for Level).
std::vector<std::vector<float>> node_values(const State& s, render::BoxColour colour);

/// The scale of a colouring over its values: viridis from the least to the 99th percentile (0 to
/// it for speeds and test counts), clearance on the diverging map reversed over +-kClearanceRange
/// (overlaps warm).
render::ColourScale disk_scale(render::DiskColour colour, const std::vector<std::vector<float>>& values);
render::ColourScale box_scale(render::BoxColour colour, const std::vector<std::vector<float>>& values);

}  // namespace mobb::viewer
