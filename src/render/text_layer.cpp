#include "text_layer.h"

#include <algorithm>
#include <cstring>

#include <stb_easy_font.h>
#include <glm/gtc/matrix_transform.hpp>

namespace mobb::render {

void TextLayer::add(const glm::vec3& world, std::string text, const glm::vec4& color, Anchor anchor) {
    labels_.push_back({world, std::move(text), color, anchor});
}

void TextLayer::add_screen(const glm::vec2& pixel, std::string text, const glm::vec4& color, Anchor anchor) {
    labels_.push_back({glm::vec3(pixel, 0.0f), std::move(text), color, anchor, true});
}

void TextLayer::draw(const DrawContext& ctx) {
    const float scale = text_scale(ctx.height);
    tris_.clear();
    std::vector<char> quads(std::size_t{64} * 1024);
    for (Label& label : labels_) {
        const glm::vec4 clip = label.screen ? glm::vec4(0, 0, 0, 1) : ctx.view_proj * glm::vec4(label.world, 1.0f);
        if (clip.w <= 0.0f) continue;  // behind the camera
        const float sx = label.screen ? label.world.x : (clip.x / clip.w * 0.5f + 0.5f) * float(ctx.width);
        const float sy = label.screen ? label.world.y : (0.5f - clip.y / clip.w * 0.5f) * float(ctx.height);
        const float w = float(stb_easy_font_width(label.text.data())) * scale;
        const float x0 = label.anchor == Anchor::Left    ? sx + 3.0f * scale
                         : label.anchor == Anchor::Right ? sx - w - 3.0f * scale
                                                         : sx - 0.5f * w;
        const float y0 = sy - 3.5f * scale;
        const float h = 7.0f * scale;  // stb_easy_font's capitals
        if (ctx.whole_labels && (x0 < 0 || x0 + w > float(ctx.width) || y0 < 0 || y0 + h > float(ctx.height))) continue;
        const int n = stb_easy_font_print(0.0f, 0.0f, label.text.data(), nullptr, quads.data(), int(quads.size()));
        for (int q = 0; q < n; ++q) {
            glm::vec3 v[4];
            for (int k = 0; k < 4; ++k) {
                float xy[2];
                std::memcpy(xy, &quads[std::size_t(q * 4 + k) * 16], sizeof xy);
                v[k] = {std::round(x0) + xy[0] * scale, std::round(y0) + xy[1] * scale, 0.0f};
            }
            tris_.quad(v[0], v[1], v[2], v[3], label.color);
        }
    }
    labels_.clear();
    ctx.use(*ctx.color);
    ctx.color->set("u_mvp", glm::ortho(0.0f, float(ctx.width), float(ctx.height), 0.0f, -1.0f, 1.0f));
    tris_.draw();
}

}  // namespace mobb::render
