// The current step of a query trace: the event's two nodes in the colour of its outcome, and for a
// hit the two colliding disks.
#pragma once
#include "batch.h"
#include "disk_layer.h"
#include "frame.h"
#include "layer.h"

namespace mobb::render {

class TraceLayer {
public:
    TraceLayer() : edges_(GL_LINES), faces_(GL_TRIANGLES) {}
    void draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass);
    /// A hit's two disks, drawn last so translucent stacks cannot wash them out.
    void draw_hit(const Frame& frame, const DrawContext& ctx, DiskLayer& disks);

private:
    Batch edges_, faces_;
};

/// The event to show, or null when there is none.
const TraceEvent* current_event(const Frame& frame);

}  // namespace mobb::render
