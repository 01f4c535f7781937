#include "box_layer.h"

namespace mobb::render {

bool shown_at_level(const Node& node, int level, int count) {
    return (node.level >= level && node.level < level + count) || (node.leaf() && node.level < level);
}

void add_box(const Obb3& world_box, double time_scale, const glm::vec4& edge, Batch& edges, const glm::vec4& face,
             Batch* faces) {
    const auto c = corners(world_box, time_scale);
    for (const auto& e : kBoxEdges) edges.line(c[std::size_t(e[0])], c[std::size_t(e[1])], edge);
    if (!faces) return;
    for (const auto& f : kBoxFaces)
        faces->quad(c[std::size_t(f[0])], c[std::size_t(f[1])], c[std::size_t(f[2])], c[std::size_t(f[3])], face);
}

void BoxLayer::rebuild(const Frame& frame) {
    edges_.clear();
    faces_.clear();
    const float face_alpha = frame.layers.all_levels ? 0.06f : 0.14f;
    for (const ClipView& clip : frame.clips) {
        if (!clip.visible) continue;
        const SpaceTimeRigid m = SpaceTimeRigid::of(clip.place);
        const auto& nodes = clip.tree->nodes();
        const bool mapped =
            frame.layers.box_colour != BoxColour::Level && clip.node_values && clip.node_values->size() == nodes.size();
        for (std::size_t n = 0; n < nodes.size(); ++n) {
            const Node& node = nodes[n];
            if (!frame.layers.all_levels && !shown_at_level(node, frame.layers.level, frame.layers.levels)) continue;
            const glm::vec3 color =
                mapped ? frame.box_scale.colour(double((*clip.node_values)[n])) : level_color(node.level);
            add_box(transformed(clip.tree->box3(node), m), frame.time_scale, glm::vec4(color, 1.0f), edges_,
                    glm::vec4(color, face_alpha), &faces_);
        }
    }
    revision_ = frame.revision;
    level_ = frame.layers.level;
    levels_ = frame.layers.levels;
    all_levels_ = frame.layers.all_levels;
    time_scale_ = frame.time_scale;
    colour_ = frame.layers.box_colour;
    colour_revision_ = frame.colour_revision;
}

void BoxLayer::draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass) {
    if (!frame.layers.boxes) return;
    if (frame.revision != revision_ || frame.layers.level != level_ || frame.layers.levels != levels_ ||
        frame.layers.all_levels != all_levels_ || frame.time_scale != time_scale_ ||
        frame.layers.box_colour != colour_ || frame.colour_revision != colour_revision_)
        rebuild(frame);
    ctx.use(*ctx.color);
    if (!translucent_pass)
        edges_.draw();
    else if (frame.layers.box_faces)
        faces_.draw();
}

}  // namespace mobb::render
