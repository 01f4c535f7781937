// Screen-aligned labels anchored at 3D points (tick marks, the cursor time), drawn with the
// stb_easy_font bitmap font so headless images need no font files.
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "batch.h"
#include "layer.h"

namespace mobb::render {

enum class Anchor { Left, Center, Right };

class TextLayer {
public:
    TextLayer() : tris_(GL_TRIANGLES) {}

    void add(const glm::vec3& world, std::string text, const glm::vec4& color, Anchor anchor = Anchor::Left);
    /// Draws and forgets the labels added since the last call.
    void draw(const DrawContext& ctx);

private:
    struct Label {
        glm::vec3 world;
        std::string text;
        glm::vec4 color;
        Anchor anchor;
    };
    std::vector<Label> labels_;
    Batch tris_;
};

}  // namespace mobb::render
