// What the renderer draws: the clips (tree, placement, skeleton), which layers, the time cursor and
// the current trace step. Plain data filled by the viewer; the renderer keeps no scene of its own.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "colour_map.h"
#include "space.h"

#include "mobb/core/path.h"
#include "mobb/core/query.h"
#include "mobb/core/trace.h"
#include "mobb/core/tree.h"
#include "mobb/io/animation.h"

namespace mobb::render {

/// What the disks' colour shows: each clip's own colour, or a per-sample quantity on a colour map.
enum class DiskColour : std::uint8_t {
    Clip,
    Radius,     ///< r, metres
    Speed,      ///< ground speed, m/s (core sample_speeds())
    Time,       ///< global start time, seconds
    Clearance,  ///< gap to the nearest other clip at the same time, metres (core nearest_clearance())
};
/// What the boxes' colour shows: their level, or a per-node quantity on a colour map.
enum class BoxColour : std::uint8_t {
    Level,
    Tightness,  ///< box volume over its sample cylinders' volume (core volume_ratio())
    Tests,      ///< how often the shown query tested the box (core tests_per_node())
};
constexpr int kDiskColours = 5, kBoxColours = 3;
/// Names on the command line and in scene files ("clip", "radius", ...; "level", "tightness", "tests").
const char* to_string(DiskColour c);
const char* to_string(BoxColour c);
/// Throw std::invalid_argument naming the valid names.
DiskColour parse_disk_colour(const std::string& name);
BoxColour parse_box_colour(const std::string& name);

struct ClipView {
    const Tree* tree = nullptr;                ///< the path and its boxes, in the clip's own frame
    const io::Animation* animation = nullptr;  ///< joints per frame for the skeleton; null for synthetic paths
    io::UpAxis up = io::UpAxis::Y;
    Placement place;
    glm::vec3 color{0.5f};
    bool visible = true;
    /// With a disk colouring other than Clip: one value per sample (owned by the caller); null draws
    /// the clip's colour. Likewise one value per tree node for a box colouring other than Level.
    const std::vector<float>* sample_values = nullptr;
    const std::vector<float>* node_values = nullptr;
};

struct Layers {
    bool grid = true;
    bool labels = true;
    bool disks = true;
    bool disks_translucent = false;
    bool boxes = false;
    bool box_faces = true;
    bool all_levels = false;
    int level = 0;          ///< 0 = root; levels below a leaf show the leaf
    int levels = 1;         ///< how many levels from `level` down are drawn
    bool cursor = true;     ///< the time-cursor plane
    bool skeletons = true;  ///< skeletons at the cursor time
    bool bodies = false;    ///< posed skeletons (crowd agents) as shaded capsules per bone (io/capsule.h), not lines
    bool trace = true;      ///< the current trace step
    DiskColour disk_colour = DiskColour::Clip;
    BoxColour box_colour = BoxColour::Level;
    bool colour_bar = true;  ///< a bar for each colouring in use, at the image's right edge
};

/// A skeleton posed by the caller rather than played from a clip (a crowd agent: the viewer picks the
/// source and frame at the cursor): frame `frame` of `animation`, its ground coordinates moved by
/// `place` (x, y, theta; t0 unused), standing on the cursor plane on height `floor` (its lowest joint).
/// Or, with `joints` set, a pose given joint by joint (a crowd agent's blended pose: ground x, y and the
/// height above its floor, metres, already placed; drawn with bones to `parents`, -1 for none).
struct PosedSkeleton {
    const io::Animation* animation = nullptr;
    std::vector<glm::dvec3> joints;
    const std::vector<int>* parents = nullptr;
    io::UpAxis up = io::UpAxis::Y;
    int frame = 0;
    Placement place;
    double floor = 0.0;
    glm::vec3 color{0.5f};
};

/// A polygon on the ground extruded over global time [t0, t1] (flat when t0 == t1): a crowd's walls,
/// obstacles and goals over the whole run, or the disks in contact at the cursor. Drawn as edges, and
/// with `fill` > 0 its side faces too, that opaque.
struct Prism {
    std::vector<std::array<double, 2>> ground;  ///< metres, in order; two points make a segment
    double t0 = 0, t1 = 0;                      ///< seconds
    glm::vec3 color{0.3f};
    float fill = 0.0f;
    bool on_top = false;  ///< drawn over everything, thick (marks that must not hide in the stacks)
};

/// The trace step to show: event `step` of `events`, a query between clips a and b.
struct TraceView {
    const Trace* events = nullptr;
    int step = -1;
    int a = -1, b = -1;
};

struct Frame {
    std::vector<ClipView> clips;
    Layers layers;
    double time_scale = 1.0;      ///< metres of height per second
    double cursor = 0.0;          ///< seconds (global time)
    double window = 0.0;          ///< > 0: only global times within this many seconds of the cursor are drawn
    double skeleton_scale = 0.5;  ///< skeleton height factor on the cursor plane
    /// Multisampling (4x MSAA) for smooth edges: about 3x the fill work of one sample per pixel under
    /// llvmpipe (bench/results/render.md). Crowds of more than kMultisampleUpTo disks never get it.
    bool multisample = true;
    TraceView trace;
    std::vector<PosedSkeleton> posed;  ///< with the skeletons layer: drawn at the cursor, over everything
    std::vector<Prism> prisms;         ///< the ones not on top count in the scene's bounds
    /// Space-time the scene spans beyond its clips and prisms, in its bounds (empty: none): a crowd read a
    /// window of frames at a time spans its world over the whole run.
    Bounds extent;
    /// Changes whenever clips, placements or trees change: the renderer rebuilds cached geometry.
    std::uint64_t revision = 0;
    /// The maps and ranges of the disk and box colourings (when not Clip / Level), and a number that
    /// changes whenever the clips' sample or node values change (the renderer re-uploads them).
    ColourScale disk_scale, box_scale;
    std::uint64_t colour_revision = 0;
};

/// Colours shared by the 3D view and the panels.
glm::vec3 clip_color(int index);
glm::vec3 level_color(int level);
glm::vec3 outcome_color(TraceOutcome outcome);

}  // namespace mobb::render
