// Each clip's path as a stack of disks: one short cylinder per sample (radius r, height dt), drawn
// instanced, one draw call per clip.
#pragma once
#include <vector>

#include <glm/vec4.hpp>

#include "frame.h"
#include "layer.h"

namespace mobb::render {

/// One cylinder's instance data: world x, world y, global start time, radius.
using DiskInstance = glm::vec4;

/// The instances of a placed path (world positions, global times).
std::vector<DiskInstance> disk_instances(const Path& path, const Placement& place);

class DiskLayer {
public:
    DiskLayer();
    ~DiskLayer();
    DiskLayer(const DiskLayer&) = delete;
    DiskLayer& operator=(const DiskLayer&) = delete;

    /// Re-uploads every clip's instances (after clips or placements change).
    void rebuild(const Frame& frame);
    /// Draws the stacks in the pass that matches their translucency.
    void draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass);
    /// Draws a few disks of spacing dt in one colour, grown by `grow` (highlights).
    void draw_marked(const DrawContext& ctx, const std::vector<DiskInstance>& disks, double dt, double time_scale,
                     const glm::vec4& color, float grow);

private:
    struct Stack {
        GLuint vao = 0, vbo = 0;
        GLsizei count = 0;
        float dt = 0;
    };
    Stack make_stack();
    void upload(Stack& stack, const std::vector<DiskInstance>& disks);
    void set_segments(int segments);

    GLuint mesh_ = 0, indices_ = 0;
    GLsizei mesh_indices_ = 0;
    int segments_ = 0;
    std::vector<Stack> stacks_;
    Stack marked_;
};

}  // namespace mobb::render
