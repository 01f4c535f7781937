// Screen-aligned labels anchored at 3D points (tick marks, the cursor time) or at pixels (colour bars),
// drawn with the stb_easy_font bitmap font so headless images need no font files. Where each goes, and which
// are left out, is lay_out_labels()'s rule (label_layout.h).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "batch.h"
#include "label_layout.h"
#include "layer.h"

namespace mobb::render {

enum class Anchor { Left, Center, Right };

/// Pixels per font pixel in a viewport `height` pixels tall: 1 below 600 rows, 2 below 1200, then 3
/// (an integer keeps the bitmap font crisp).
inline float text_scale(int height) { return height >= 1200 ? 3.0f : height >= 600 ? 2.0f : 1.0f; }

class TextLayer {
public:
    TextLayer() : tris_(GL_TRIANGLES) {}

    /// A label at a 3D point, vertically centred on it, moved by `offset` font pixels (scaled with the text;
    /// y down).
    void add(const glm::vec3& world, std::string text, const glm::vec4& color, Anchor anchor, LabelRole role,
             const glm::vec2& offset = {0.0f, 0.0f});
    /// A tick label left (or right) of the point `world`, which goes right (or left) of `across` instead when
    /// there is no room on its own side: the two ends of a tick mark across its axis.
    void add_tick(const glm::vec3& world, const glm::vec3& across, std::string text, const glm::vec4& color,
                  Anchor anchor);
    /// An overlay's label at a pixel position (x right, y down from the top left), vertically centred on it.
    void add_screen(const glm::vec2& pixel, std::string text, const glm::vec4& color, Anchor anchor = Anchor::Left);
    /// Keeps labels off a box drawn this frame (a colour bar); pixels as for add_screen.
    void reserve(const TextBox& box) { reserved_.push_back(box); }
    /// Lays out and draws the labels added since the last call, then forgets them.
    void draw(const DrawContext& ctx);
    /// What the last draw drew, boxes in the viewport's pixels from its top-left corner.
    const std::vector<DrawnLabel>& drawn() const { return drawn_; }

private:
    void plate(const TextBox& box, float scale);

    struct Label {
        glm::vec3 world;
        std::string text;
        glm::vec4 color;
        Anchor anchor;
        LabelRole role;
        glm::vec2 offset{0.0f};
        bool screen = false;                ///< world.x, world.y are pixels
        std::optional<glm::vec3> across{};  ///< add_tick's other side
    };
    std::vector<Label> labels_;
    std::vector<TextBox> reserved_;
    std::vector<DrawnLabel> drawn_;
    Batch tris_;
};

}  // namespace mobb::render
