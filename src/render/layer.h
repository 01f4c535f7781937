// What every layer needs to draw one frame.
#pragma once
#include <glm/mat4x4.hpp>

#include "shader.h"
#include "space.h"

namespace mobb::render {

struct DrawContext {
    glm::mat4 view_proj{1.0f};
    int width = 1, height = 1;
    const Program* color = nullptr;  ///< color.vert/.frag: lines, triangles, text
    const Program* disk = nullptr;   ///< disk.vert/.frag: instanced cylinders
    Bounds bounds;                   ///< the scene in space-time, for the grid and the cursor plane
};

}  // namespace mobb::render
