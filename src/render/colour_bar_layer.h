// Colour bars: for each colouring in use (disks, boxes) a vertical bar of its map at the image's right
// edge, its range's ends and middle printed beside it and "quantity (unit)" above it.
#pragma once
#include <string>

#include "batch.h"
#include "frame.h"
#include "layer.h"
#include "text_layer.h"

namespace mobb::render {

/// The number printed at a colour bar's tick: three significant digits.
std::string bar_label(double value);

class ColourBarLayer {
public:
    ColourBarLayer() : quads_(GL_TRIANGLES), lines_(GL_LINES) {}
    /// Draws the bars of the frame's colourings (with layers.colour_bar) in screen space.
    void draw(const Frame& frame, const DrawContext& ctx, TextLayer& text);

private:
    /// Adds one bar whose top edge is `top` pixels down; returns its bottom edge, labels included.
    float add_bar(const ColourScale& scale, const DrawContext& ctx, float right, float top, TextLayer& text);

    Batch quads_, lines_;
};

}  // namespace mobb::render
