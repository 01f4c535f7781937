#include "grid_layer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace mobb::render {

double tick_step(double range, int most) {
    double step = 1e-3;
    for (int k = 0; k < 24 && range / step > most; ++k) step *= (k % 3 == 1) ? 2.5 : 2.0;  // 1, 2, 5, 10, ...
    return step;
}

Bounds grid_bounds(const Bounds& scene) {
    // Whole metres around the scene, widened to kMinGridSide a side so that a scene standing in place
    // still shows a few metre lines and their labels.
    static constexpr double kMinGridSide = 3;  // metres
    auto side = [](double lo, double hi) {
        double a = std::floor(lo), b = std::ceil(hi);
        const double extra = std::max(0.0, kMinGridSide - (b - a));
        a -= std::floor(extra / 2);
        return std::pair{a, a + std::max(kMinGridSide, b - a)};
    };
    const auto [x0, x1] = side(scene.lo.x, scene.hi.x);
    const auto [y0, y1] = side(scene.lo.y, scene.hi.y);
    Bounds b;
    b.add({x0, y0, std::min(0.0, scene.lo.z)});
    b.add({x1, y1, std::max(scene.hi.z, std::min(0.0, scene.lo.z) + 1e-3)});
    return b;
}

static std::string format(double value, double step, const char* unit) {
    if (std::fabs(value) < 1e-6 * step) value = 0.0;  // no "-0 m"
    char text[32];
    std::snprintf(text, sizeof text, step < 1 ? "%.1f %s" : "%.0f %s", value, unit);
    return text;
}

void GridLayer::draw(const Frame& frame, const DrawContext& ctx, TextLayer& text) {
    if (!frame.layers.grid || ctx.bounds.empty) return;
    const double ts = frame.time_scale;
    const Bounds grid = grid_bounds(ctx.bounds);
    const double x0 = grid.lo.x, x1 = grid.hi.x, y0 = grid.lo.y, y1 = grid.hi.y;
    const glm::vec4 minor(0.78f, 0.79f, 0.82f, 1.0f), major(0.55f, 0.56f, 0.60f, 1.0f), ink(0.15f, 0.15f, 0.2f, 1.0f);
    lines_.clear();
    // Integer counters: a float one drifts from the values it should take (here whole metres, x0 and y0 whole).
    for (int i = 0; x0 + i <= x1; ++i) {
        const double x = x0 + i;
        lines_.line(to_gl(x, y0, 0, ts), to_gl(x, y1, 0, ts), std::fmod(std::fabs(x), 5.0) < 0.5 ? major : minor);
    }
    for (int i = 0; y0 + i <= y1; ++i) {
        const double y = y0 + i;
        lines_.line(to_gl(x0, y, 0, ts), to_gl(x1, y, 0, ts), std::fmod(std::fabs(y), 5.0) < 0.5 ? major : minor);
    }

    // Time axis at the grid's (x0, y0) corner, from t = 0 (or earlier) to the last sample.
    const double t0 = grid.lo.z, t1 = grid.hi.z;
    lines_.line(to_gl(x0, y0, t0, ts), to_gl(x0, y0, t1, ts), ink);
    const double step = tick_step(t1 - t0, 10);
    const double tick = 0.15 * std::max(1.0, (x1 - x0) / 10.0);
    if (frame.layers.labels) {
        char caption[48];
        std::snprintf(caption, sizeof caption, "time (%.2g m per s)", ts);
        // A line above the axis's top, where its top tick label does not reach.
        text.add(to_gl(x0, y0, t1, ts), caption, ink, Anchor::Right, LabelRole::Title, {0.0f, -11.0f});
    }
    for (int k = int(std::ceil(t0 / step)); k * step <= t1 + 1e-9; ++k) {
        const double t = k * step;
        lines_.line(to_gl(x0 - tick, y0, t, ts), to_gl(x0 + tick, y0, t, ts), ink);
        if (frame.layers.labels)
            text.add_tick(to_gl(x0 - tick, y0, t, ts), to_gl(x0 + tick, y0, t, ts), format(t, step, "s"), ink,
                          Anchor::Right);
    }
    // Metre labels along the front edge.
    if (frame.layers.labels) {
        const double mstep = tick_step(x1 - x0, 8) < 1 ? 1 : tick_step(x1 - x0, 8);
        for (int k = int(std::ceil((x0 + 0.5) / mstep)); k * mstep <= x1; ++k)
            text.add(to_gl(k * mstep, y0, 0, ts), format(k * mstep, 1, "m"), major, Anchor::Center, LabelRole::Tick);
    }
    ctx.use(*ctx.color);
    lines_.draw();
}

}  // namespace mobb::render
