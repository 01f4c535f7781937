// Each clip's path as a stack of disks: one short cylinder per sample (radius r, height dt), drawn
// instanced, one draw call per clip. Crowds far from the camera are drawn at a level of detail k:
// one sheared cylinder per k consecutive samples (disk_lod.h), or, where nothing cuts the stacks
// open and they are drawn opaque in their clip's colour, one tube through those groups (tube_mesh()):
// one draw call per run of chunks at one k.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "disk_lod.h"
#include "frame.h"
#include "layer.h"

namespace mobb::render {

/// What the last draw of the stacks drew: disks stood for, instances (or groups of a tube) drawn, the
/// range of k.
struct DiskStats {
    std::size_t disks = 0, instances = 0;
    int k_min = 0, k_max = 0;
};

class DiskLayer {
public:
    DiskLayer();
    ~DiskLayer();
    DiskLayer(const DiskLayer&) = delete;
    DiskLayer& operator=(const DiskLayer&) = delete;

    /// Forgets every clip's instances (after clips or placements change); they are rebuilt lazily,
    /// per level of detail, when drawn.
    void rebuild(const Frame& frame);
    /// Draws the stacks in the pass that matches their translucency.
    void draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass);
    /// Draws a few disks of spacing dt in one colour, grown by `grow` (highlights).
    void draw_marked(const DrawContext& ctx, const std::vector<DiskInstance>& disks, double dt, double time_scale,
                     const glm::vec4& color, float grow);
    /// The stacks' last draw.
    const DiskStats& stats() const { return stats_; }

private:
    static constexpr int kLevels = 9;  ///< k = 1, 2, 4 .. 256 (kDiskLodMaxK)
    struct Stack {
        GLuint vao = 0, vbo = 0;
        GLsizei count = 0;
        bool built = false;
        GLuint values = 0;                                  ///< one float per instance (location 4)
        std::uint64_t values_revision = ~std::uint64_t(0);  ///< the frame's colour_revision uploaded
    };
    struct Tube {
        GLuint vao = 0, vbo = 0, ibo = 0;
        TubeMesh shape;  ///< its index ranges (vertices and indices live in the buffers)
        bool built = false;
    };
    struct Clip {
        std::array<Stack, kLevels> lods;  ///< by log2 k
        std::array<Tube, kLevels> tubes;  ///< by log2 k; level 0 unused
        std::vector<Bounds> chunks;       ///< space-time bounds of each kDiskChunk samples: LOD, culling
        float dt = 0;
    };
    struct SampleSpan {
        std::int64_t first = 0, end = 0;  ///< samples [first, end)
    };
    struct Run {  ///< consecutive chunks of a clip drawn at one level of detail
        std::size_t clip = 0;
        SampleSpan span;
        int k = 1;
    };
    /// The runs of every visible clip's chunks in view, chunks at one k in a row joined.
    std::vector<Run> runs_in_view(const Frame& frame, const DrawContext& ctx);
    /// Draws samples [span) of clip c as its tube at level of detail k > 1; returns the groups drawn.
    GLsizei draw_tube(const Frame& frame, std::size_t c, SampleSpan span, int k);
    Tube& tube_at(const ClipView& clip, Clip& c, int k) const;
    static void release(Tube& t);
    static SampleSpan in_window(const Frame& frame, const ClipView& clip);
    /// Draws samples [span) of clip c at level of detail k; returns the instances drawn.
    GLsizei draw_span(const Frame& frame, const DrawContext& ctx, std::size_t c, SampleSpan span, int k);
    static void point_at(const Stack& s, GLsizei first, bool grouped, bool mapped);
    /// Points location 4 at the clip's values (per instance of the stack) when the frame maps them to
    /// colours; returns whether it does.
    bool map_values(const Frame& frame, const ClipView& clip, Stack& s, int group);
    static int level_of(int k);  ///< log2 of the group size that stands for k samples
    Stack make_stack(bool grouped) const;
    void upload(Stack& stack, const std::vector<DiskInstance>& disks);
    void upload(Stack& stack, const std::vector<DiskGroup>& groups);
    Stack& stack_at(const ClipView& clip, Clip& c, int k);
    void set_segments(int segments);
    static void release(Stack& s);

    GLuint mesh_ = 0, indices_ = 0;
    GLsizei mesh_indices_ = 0;
    int segments_ = 0;
    std::size_t total_ = 0;  ///< disks in the scene
    std::vector<Clip> clips_;
    Stack marked_;
    DiskStats stats_;
};

}  // namespace mobb::render
