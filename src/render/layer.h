// What every layer needs to draw one frame.
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "shader.h"
#include "space.h"

namespace mobb::render {

/// The viewport's clear colour, and the plates behind titles (TextLayer) so that they read over lines.
inline constexpr glm::vec4 kBackground(0.965f, 0.965f, 0.972f, 1.0f);

struct DrawContext {
    glm::mat4 view_proj{1.0f};
    int width = 1, height = 1;
    const Program* color = nullptr;  ///< color.vert/.frag: lines, triangles, text
    const Program* disk = nullptr;   ///< disk.vert/.frag: instanced cylinders
    const Program* tube = nullptr;   ///< tube.vert, disk.frag: stacks as tubes (levels of detail)
    Bounds bounds;                   ///< the scene in space-time, for the grid and the cursor plane
    /// GL heights (t * time_scale) kept by the clip planes: the frame's time window for what lies in
    /// space-time (disks, boxes, prisms, the trace), everything for the grid, the cursor and text.
    float clip_lo = -1e30f, clip_hi = 1e30f;

    /// Makes `p` current with this context's matrix and clip planes (text then sets its own matrix).
    void use(const Program& p) const {
        p.use();
        p.set("u_mvp", view_proj);
        p.set("u_clip_lo", clip_lo);
        p.set("u_clip_hi", clip_hi);
    }
};

}  // namespace mobb::render
