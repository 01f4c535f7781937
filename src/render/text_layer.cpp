#include "text_layer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <stb_easy_font.h>
#include <glm/gtc/matrix_transform.hpp>

namespace mobb::render {

namespace {

constexpr std::size_t kVertexBytes = 16;  ///< stb_easy_font's vertex: x, y, z floats and a colour

/// The text's glyph quads from stb_easy_font, in font pixels from the text's origin; `ink` gets their bounds.
std::vector<glm::vec2> glyph_corners(const std::string& text, TextBox& ink) {
    static std::vector<char> quads(std::size_t{64} * 1024);
    const int n =
        stb_easy_font_print(0.0f, 0.0f, const_cast<char*>(text.c_str()), nullptr, quads.data(), int(quads.size()));
    std::vector<glm::vec2> corners(std::size_t(n) * 4);
    ink = {1e30f, 1e30f, -1e30f, -1e30f};
    for (std::size_t v = 0; v < corners.size(); ++v) {
        float xy[2];
        std::memcpy(xy, &quads[v * kVertexBytes], sizeof xy);
        corners[v] = {xy[0], xy[1]};
        ink = {std::min(ink.x0, xy[0]), std::min(ink.y0, xy[1]), std::max(ink.x1, xy[0]), std::max(ink.y1, xy[1])};
    }
    if (corners.empty()) ink = {};
    return corners;
}

}  // namespace

void TextLayer::add(const glm::vec3& world, std::string text, const glm::vec4& color, Anchor anchor, LabelRole role,
                    const glm::vec2& offset) {
    labels_.push_back({world, std::move(text), color, anchor, role, offset});
}

void TextLayer::add_tick(const glm::vec3& world, const glm::vec3& across, std::string text, const glm::vec4& color,
                         Anchor anchor) {
    labels_.push_back({world, std::move(text), color, anchor, LabelRole::Tick, {}, false, across});
}

void TextLayer::add_screen(const glm::vec2& pixel, std::string text, const glm::vec4& color, Anchor anchor) {
    labels_.push_back({glm::vec3(pixel, 0.0f), std::move(text), color, anchor, LabelRole::Overlay, {}, true});
}

void TextLayer::draw(const DrawContext& ctx) {
    const float scale = text_scale(ctx.height), width = float(ctx.width), height = float(ctx.height);
    // Each label's box where its anchor puts it: left, right or centre of the point, vertically centred.
    std::vector<LabelSpot> spots;
    std::vector<std::vector<glm::vec2>> glyphs;
    std::vector<TextBox> inks;
    std::vector<const Label*> shown;
    const auto pixel = [&](const glm::vec3& world, glm::vec2& at) {
        const glm::vec4 clip = ctx.view_proj * glm::vec4(world, 1.0f);
        if (clip.w <= 0.0f) return false;  // behind the camera
        at = {(clip.x / clip.w * 0.5f + 0.5f) * width, (0.5f - clip.y / clip.w * 0.5f) * height};
        return true;
    };
    for (const Label& label : labels_) {
        glm::vec2 at(label.world);
        if (!label.screen && !pixel(label.world, at)) continue;
        TextBox ink;
        std::vector<glm::vec2> corners = glyph_corners(label.text, ink);
        const float w = float(stb_easy_font_width(const_cast<char*>(label.text.c_str()))) * scale;
        const auto box_at = [&](const glm::vec2& p, Anchor anchor) {
            const float x = anchor == Anchor::Left    ? p.x + 3.0f * scale
                            : anchor == Anchor::Right ? p.x - w - 3.0f * scale
                                                      : p.x - 0.5f * w;
            const float ox = std::round(x + label.offset.x * scale);
            const float oy = std::round(p.y + (label.offset.y - 3.5f) * scale);
            return TextBox{ox + ink.x0 * scale, oy + ink.y0 * scale, ox + ink.x1 * scale, oy + ink.y1 * scale};
        };
        LabelSpot spot{box_at(at, label.anchor), label.role, at.x >= 0 && at.x <= width && at.y >= 0 && at.y <= height};
        glm::vec2 across;
        if (label.across && label.anchor != Anchor::Center && pixel(*label.across, across))
            spot.other_side = box_at(across, label.anchor == Anchor::Left ? Anchor::Right : Anchor::Left);
        spots.push_back(spot);
        glyphs.push_back(std::move(corners));
        inks.push_back(ink);
        shown.push_back(&label);
    }
    const std::vector<bool> drawn = lay_out_labels(spots, reserved_, width, height, label_gap(scale));
    tris_.clear();
    drawn_.clear();
    for (std::size_t k = 0; k < spots.size(); ++k) {
        if (!drawn[k]) continue;
        const Label& label = *shown[k];
        drawn_.push_back({label.text, spots[k].box, label.role});
        if (label.role == LabelRole::Title) plate(spots[k].box, scale);
        // The glyphs keep their place in the box the layout chose.
        const glm::vec2 origin(spots[k].box.x0 - inks[k].x0 * scale, spots[k].box.y0 - inks[k].y0 * scale);
        const std::vector<glm::vec2>& g = glyphs[k];
        for (std::size_t q = 0; q + 3 < g.size(); q += 4) {
            glm::vec3 v[4];
            for (std::size_t c = 0; c < 4; ++c) v[c] = glm::vec3(origin + g[q + c] * scale, 0.0f);
            tris_.quad(v[0], v[1], v[2], v[3], label.color);
        }
    }
    labels_.clear();
    reserved_.clear();
    ctx.use(*ctx.color);
    // Pixels from the top-left corner: bottom is the height, top 0 (not a swap).
    ctx.color->set("u_mvp",
                   glm::ortho(0.0f, width, height, 0.0f, -1.0f, 1.0f));  // NOLINT(readability-suspicious-call-argument)
    glEnable(GL_BLEND);                                                  // the plates; glyphs are opaque
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    tris_.draw();
    glDisable(GL_BLEND);
}

// A title (the cursor's time, the time axis' caption) sits on a plate of the background, mostly opaque, so
// that the lines and disks it is placed over do not cut through its glyphs.
void TextLayer::plate(const TextBox& box, float scale) {
    constexpr float kOpacity = 0.85f;
    const float pad = 0.5f * label_gap(scale);  // half the room between labels: plates never meet
    const float x0 = box.x0 - pad, y0 = box.y0 - pad, x1 = box.x1 + pad, y1 = box.y1 + pad;
    tris_.quad({x0, y0, 0.0f}, {x1, y0, 0.0f}, {x1, y1, 0.0f}, {x0, y1, 0.0f},
               glm::vec4(glm::vec3(kBackground), kOpacity));
}

}  // namespace mobb::render
