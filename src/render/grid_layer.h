// The ground grid (one line per metre, darker every 5 m) and the vertical time axis with labelled ticks.
#pragma once
#include "batch.h"
#include "frame.h"
#include "layer.h"
#include "text_layer.h"

namespace mobb::render {

class GridLayer {
public:
    GridLayer() : lines_(GL_LINES) {}
    void draw(const Frame& frame, const DrawContext& ctx, TextLayer& text);

private:
    Batch lines_;
};

/// What the grid covers for a scene's bounds: the ground they cover rounded out to whole metres (at least
/// 3 m a side), and in time from 0 (or earlier) to the last sample - the time axis stands at its
/// (lo.x, lo.y) corner. (It reached a metre further on every side; framing the scene and the axis then
/// left the clips a third of the view.)
Bounds grid_bounds(const Bounds& scene);

/// A "nice" step (1, 2 or 5 times a power of ten) giving at most `most` ticks over `range`.
double tick_step(double range, int most);

}  // namespace mobb::render
