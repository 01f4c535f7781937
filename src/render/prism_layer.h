// Prisms (frame.h): a crowd's walls, obstacles and goals as polygons extruded over the run, and the
// disks in contact at the cursor drawn on top.
#pragma once
#include "batch.h"
#include "frame.h"
#include "layer.h"

namespace mobb::render {

class PrismLayer {
public:
    PrismLayer() : edges_(GL_LINES), faces_(GL_TRIANGLES), top_(GL_LINES) {}
    /// Edges in the opaque pass, faces in the translucent one.
    void draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass);
    /// The prisms marked on_top, over everything.
    void draw_on_top(const Frame& frame, const DrawContext& ctx);

private:
    Batch edges_, faces_, top_;
};

}  // namespace mobb::render
