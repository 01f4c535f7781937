// Level of detail for the disk stacks: pure functions, no GL. When one sample's cylinder is far below
// a pixel tall on screen (crowds: 100 clips of 3,600 samples seen whole), a stack is drawn with one
// cylinder per group of k consecutive samples instead of one per sample.
//
// A group's cylinder is sheared, not upright: its axis runs from the centre of the group's first disk
// (at the group's start time) to the centre of the next group's first disk (at the group's end time),
// so consecutive groups meet centre to centre and a stack never shows a gap or a step. Its radius is
// the smallest one that keeps every disk of the group inside for the whole of the disk's time slot:
// max over the group of r_i + (distance from c_i to the axis at the slot's start or end). For smooth
// motion that is max r plus a fraction of one sample's step, so the silhouette is conservative and
// barely wider than the stack's. The vertical extent is exact: a group spans its samples' time slots.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "frame.h"
#include "space.h"

namespace mobb::render {

/// One cylinder's instance data: world x, world y, global start time, radius.
using DiskInstance = glm::vec4;

/// One group's instance data: `base` as a DiskInstance (first disk's centre, start time, group
/// radius); `shift` = (world dx, world dy) from the base centre to the top centre, 1 when the top cap
/// lies inside the next group of the same chunk (its radius is at least this one's: the cap is a disk
/// of this radius on the next group's base centre, within its base disk) else 0, and the number of
/// samples in the group (its height in units of dt).
struct DiskGroup {
    glm::vec4 base;
    glm::vec4 shift;
};

/// LOD is used only for crowds, as coarse disks and single sampling are (see DiskLayer): ordinary
/// scenes, whatever their zoom, always draw one cylinder per sample.
constexpr std::size_t kDiskLodAbove = 100000;
/// A group may be at most this many pixels tall on screen (at the clip's point nearest the camera).
constexpr double kDiskLodPixels = 4.0;
constexpr int kDiskLodMaxK = 256;

/// Samples per drawn cylinder: 1 for scenes of at most kDiskLodAbove disks or when one sample's
/// cylinder is more than kDiskLodPixels / 2 tall; else the largest power of two k <= kDiskLodMaxK with
/// k * sample_pixels <= kDiskLodPixels.
int disk_lod(double sample_pixels, std::size_t scene_disks);

/// Pixels per metre (perpendicular to the view) at the point of the GL-world box [lo, hi] nearest
/// the camera, in a viewport `height` pixels tall; infinity when the box reaches the camera plane.
double nearest_pixels_per_metre(const glm::mat4& view_proj, int height, const glm::vec3& lo, const glm::vec3& hi);

/// Space-time bounds of a placed path's disks (world x, y; global time from start to end).
Bounds path_bounds(const Path& path, const Placement& place);

/// Samples per chunk of a stack: each chunk gets its own level of detail and is culled on its own. A
/// multiple of kDiskLodMaxK, so chunks start on a group boundary at every level.
constexpr int kDiskChunk = 2 * kDiskLodMaxK;

/// Space-time bounds of each chunk of kDiskChunk samples of a placed path (the last may be shorter).
std::vector<Bounds> chunk_bounds(const Path& path, const Placement& place);

/// Whether GL-world box [lo, hi] lies wholly outside the view (beyond one side of the clip volume).
bool outside_view(const glm::mat4& view_proj, const glm::vec3& lo, const glm::vec3& hi);

/// The LOD of one clip of space-time bounds `bounds` and sample spacing dt in a frame.
int clip_lod(const Bounds& bounds, double dt, double time_scale, std::size_t scene_disks, const glm::mat4& view_proj,
             int height);

/// Every clip's LOD in a frame drawn with view_proj into a viewport `height` pixels tall.
std::vector<int> frame_lods(const Frame& frame, const glm::mat4& view_proj, int height);

/// The instances of a placed path (world positions, global times).
std::vector<DiskInstance> disk_instances(const Path& path, const Placement& place);

/// Groups of k consecutive disks (the last group may hold fewer), as described above.
std::vector<DiskGroup> group_disks(const std::vector<DiskInstance>& disks, int k);

/// A stack's groups as one tube: a ring of `segments` vertices at each boundary between groups, the
/// groups' sides joining consecutive rings, a cap at either end. Ring j lies on group j's base centre
/// (the last ring on the last group's top centre) at the boundary's time, its radius the larger of
/// the two groups it joins, so each segment of the tube holds its group's sheared cylinder, hence its
/// disks. Half the vertices and two thirds of the triangles of the groups drawn as cylinders with caps.
struct TubeVertex {
    glm::vec3 pos;  ///< world x, world y, global time
    /// Radial direction (x, y) and the side's outward slope m: metres per second the surface moves
    /// along that direction (its normal in space-time is (dir, -m / time_scale)); caps: (0, 0, 0, +-1).
    glm::vec4 dir;
};
struct TubeMesh {
    std::vector<TubeVertex> vertices;    ///< rings 0..groups, then the two caps' copies of the end rings
    std::vector<std::uint32_t> indices;  ///< bottom cap, then 6 * segments per group in order, top cap
    std::size_t groups = 0;
    int segments = 0;
    std::size_t cap_indices() const { return 3 * std::size_t(segments - 2); }
    /// First index and count of groups [g0, g1), with the caps where the range reaches an end.
    std::size_t first_index(std::size_t g0) const {
        return g0 == 0 ? 0 : cap_indices() + 6 * std::size_t(segments) * g0;
    }
    std::size_t end_index(std::size_t g1) const {
        return cap_indices() + 6 * std::size_t(segments) * g1 + (g1 == groups ? cap_indices() : 0);
    }
};
TubeMesh tube_mesh(const std::vector<DiskGroup>& groups, double dt, int segments);

/// The values of groups of k consecutive samples (as group_disks() groups them): each group's mean,
/// or with `least` its smallest (clearance: a group holding a collision shows it).
std::vector<float> group_values(const std::vector<float>& values, int k, bool least);

}  // namespace mobb::render
