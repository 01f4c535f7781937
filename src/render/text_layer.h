// Screen-aligned labels anchored at 3D points (tick marks, the cursor time), drawn with the
// stb_easy_font bitmap font so headless images need no font files.
#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "batch.h"
#include "layer.h"

namespace mobb::render {

enum class Anchor { Left, Center, Right };

/// Pixels per font pixel in a viewport `height` pixels tall: 1 below 600 rows, 2 below 1200, then 3
/// (an integer keeps the bitmap font crisp).
inline float text_scale(int height) { return height >= 1200 ? 3.0f : height >= 600 ? 2.0f : 1.0f; }

class TextLayer {
public:
    TextLayer() : tris_(GL_TRIANGLES) {}

    void add(const glm::vec3& world, std::string text, const glm::vec4& color, Anchor anchor = Anchor::Left);
    /// A label at a pixel position (x right, y down from the top left), vertically centred on it.
    void add_screen(const glm::vec2& pixel, std::string text, const glm::vec4& color, Anchor anchor = Anchor::Left);
    /// Draws and forgets the labels added since the last call.
    void draw(const DrawContext& ctx);

private:
    struct Label {
        glm::vec3 world;
        std::string text;
        glm::vec4 color;
        Anchor anchor;
        bool screen = false;  ///< world.x, world.y are pixels
    };
    std::vector<Label> labels_;
    Batch tris_;
};

}  // namespace mobb::render
