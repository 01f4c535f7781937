// The boxes of each clip's tree at one level (or every level): edges plus translucent faces,
// coloured by level. Geometry is cached until the clips or the level change.
#pragma once
#include <cstdint>

#include "batch.h"
#include "frame.h"
#include "layer.h"

namespace mobb::render {

/// Nodes shown at `level`: the nodes of that level, and leaves above it (a short branch shows its leaf).
bool shown_at_level(const Node& node, int level, int count = 1);

/// Adds one placed box's edges and (when faces is not null) faces.
void add_box(const Obb3& world_box, double time_scale, const glm::vec4& edge, Batch& edges, const glm::vec4& face,
             Batch* faces);

class BoxLayer {
public:
    BoxLayer() : edges_(GL_LINES), faces_(GL_TRIANGLES) {}
    void draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass);

private:
    void rebuild(const Frame& frame);

    Batch edges_, faces_;
    std::uint64_t revision_ = ~std::uint64_t(0);
    int level_ = -1, levels_ = 0;
    bool all_levels_ = false;
    double time_scale_ = 0;
    BoxColour colour_ = BoxColour::Level;
    std::uint64_t colour_revision_ = 0;
};

}  // namespace mobb::render
