#include "colour_bar_layer.h"

#include <algorithm>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

namespace mobb::render {

namespace {
constexpr int kSteps = 64;  ///< flat bands per bar
}

std::string bar_label(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

float ColourBarLayer::add_bar(const ColourScale& scale, const DrawContext& ctx, float right, float top,
                              TextLayer& text) {
    const float s = text_scale(ctx.height);
    const glm::vec4 ink(0.15f, 0.15f, 0.2f, 1.0f);
    const float width = 14.0f * s, height = std::min(150.0f * s, 0.3f * float(ctx.height));
    const float x1 = right, x0 = right - width, y0 = top + 14.0f * s, y1 = y0 + height;
    const std::string title = scale.unit.empty() ? scale.label : scale.label + " (" + scale.unit + ")";
    text.add_screen({x1, top + 4.0f * s}, title, ink, Anchor::Right);
    for (int k = 0; k < kSteps; ++k) {
        // Band k runs from the top (the largest values) down, whichever way the map runs.
        const float a = y0 + height * float(k) / kSteps, b = y0 + height * float(k + 1) / kSteps;
        const double value = scale.most() + (scale.least() - scale.most()) * (double(k) + 0.5) / kSteps;
        const glm::vec4 c(scale.colour(value), 1.0f);
        quads_.quad({x0, a, 0}, {x1, a, 0}, {x1, b, 0}, {x0, b, 0}, c);
    }
    text.reserve({x0, y0, x1, y1});
    lines_.line({x0, y0, 0}, {x1, y0, 0}, ink);
    lines_.line({x1, y0, 0}, {x1, y1, 0}, ink);
    lines_.line({x1, y1, 0}, {x0, y1, 0}, ink);
    lines_.line({x0, y1, 0}, {x0, y0, 0}, ink);
    for (int k = 0; k <= 2; ++k) {
        const float y = y0 + height * float(k) / 2.0f;
        const double value = scale.most() + (scale.least() - scale.most()) * double(k) / 2.0;
        lines_.line({x0 - 4.0f * s, y, 0}, {x0, y, 0}, ink);
        text.add_screen({x0 - 4.0f * s, y}, bar_label(value), ink, Anchor::Right);
    }
    return y1 + 8.0f * s;
}

void ColourBarLayer::draw(const Frame& frame, const DrawContext& ctx, TextLayer& text) {
    if (!frame.layers.colour_bar) return;
    const bool disks = frame.layers.disks && frame.layers.disk_colour != DiskColour::Clip;
    const bool boxes = frame.layers.boxes && frame.layers.box_colour != BoxColour::Level;
    if (!disks && !boxes) return;
    quads_.clear();
    lines_.clear();
    const float s = text_scale(ctx.height);
    const float right = float(ctx.width) - 10.0f * s;
    float top = 10.0f * s;
    if (disks) top = add_bar(frame.disk_scale, ctx, right, top, text);
    if (boxes) add_bar(frame.box_scale, ctx, right, top, text);
    ctx.use(*ctx.color);
    ctx.color->set("u_mvp", glm::ortho(0.0f, float(ctx.width), float(ctx.height), 0.0f, -1.0f, 1.0f));
    quads_.draw();
    lines_.draw();
}

}  // namespace mobb::render
