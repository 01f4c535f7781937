#include "mobb/core/tree.h"
#include "mobb/core/assert.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace mobb {

namespace {

bool one_level(TreeType t) { return t == TreeType::Mobb1 || t == TreeType::Umobb1; }

// Which box a node at this level wants (the fit may still fall back from 3D to 2D).
BoxKind wanted_kind(TreeType t, int level) {
    switch (t) {
        case TreeType::Mobb:
        case TreeType::Mobb1: return BoxKind::Box2;
        case TreeType::Umobb:
        case TreeType::Umobb1: return BoxKind::Box3;
        case TreeType::Hybrid1: return level == 0 ? BoxKind::Box2 : BoxKind::Box3;
        case TreeType::Hybrid2: return level == 0 ? BoxKind::Box3 : BoxKind::Box2;
    }
    return BoxKind::Box2;
}

}  // namespace

static_assert(
    [] {
        for (int i = 0; i < kTreeTypeCount; ++i)
            if (int(kTreeTypes[i].type) != i) return false;
        return true;
    }(),
    "kTreeTypes lists the types in TreeType order");

const char* to_string(TreeType type) { return kTreeTypes[int(type)].name; }

const char* label(TreeType type) { return kTreeTypes[int(type)].label; }

std::string tree_type_names() {
    std::string out;
    for (const TreeTypeName& t : kTreeTypes) out += (out.empty() ? "" : ", ") + std::string(t.name);
    return out;
}

TreeType parse_tree_type(const std::string& name) {
    for (const TreeTypeName& t : kTreeTypes)
        if (name == t.name) return t.type;
    throw std::invalid_argument("unknown tree type '" + name + "' (" + tree_type_names() + ")");
}

TreeOptions parse_tree_options(const std::string& type, int n_min, const std::string& fit) {
    TreeOptions o;
    o.type = parse_tree_type(type);
    o.n_min = n_min;
    o.fit = parse_axis_fit(fit);
    return o;
}

Tree Tree::build(Path path, const TreeOptions& options) {
    validate(path);
    if (path.samples.empty()) throw std::invalid_argument("tree: the path has no samples");
    if (path.samples.size() > 0x7fffffffu) throw std::invalid_argument("tree: too many samples");
    if (options.n_min < 1) throw std::invalid_argument("tree: n_min must be at least 1");
    Tree tree;
    tree.path_ = std::move(path);
    tree.options_ = options;
    tree.margin_ = fit_margin(tree.path_);
    tree.nodes_.reserve(2 * (tree.path_.size() / std::size_t(options.n_min)) + 1);
    tree.nodes_.resize(1);
    tree.fill(0, 0, std::uint32_t(tree.path_.size()), 0);
    return tree;
}

// Fits node `index`'s box, then splits it at the temporal midpoint while it holds more than n_min
// samples. Children are appended as adjacent pairs, so a node needs only its first child's index.
void Tree::fill(int index, std::uint32_t first, std::uint32_t end, int level) {
    MOBB_ASSERT(first < end && end <= path_.samples.size());
    MOBB_ASSERT(index >= 0 && std::size_t(index) < nodes_.size());
    MOBB_ASSERT(level < 255);  // Node::level is 8 bits; a 32-bit sample count splits 32 times at most
    Node node;
    node.first = first;
    node.end = end;
    node.level = std::uint8_t(level);
    Obb3 box3;
    if (wanted_kind(options_.type, level) == BoxKind::Box3 && fit_obb3(path_, first, end, box3)) {
        node.kind = BoxKind::Box3;
        node.box = std::uint32_t(box3s_.size());
        box3s_.push_back(box3);
    } else {
        node.kind = BoxKind::Box2;
        node.box = std::uint32_t(box2s_.size());
        box2s_.push_back(fit_obb2(path_, first, end, options_.fit));
    }
    depth_ = std::max(depth_, level + 1);
    const std::uint32_t count = end - first;
    const bool split = !one_level(options_.type) && count > std::uint32_t(options_.n_min);
    if (split) {
        node.child = std::int32_t(nodes_.size());
        nodes_.resize(nodes_.size() + 2);
    }
    nodes_[std::size_t(index)] = node;
    if (split) {
        const std::uint32_t mid = first + count / 2;
        fill(node.child, first, mid, level + 1);
        fill(node.child + 1, mid, end, level + 1);
    }
}

Obb3 Tree::box3(const Node& node) const {
    MOBB_ASSERT(node.box < (node.kind == BoxKind::Box3 ? box3s_.size() : box2s_.size()));
    if (node.kind == BoxKind::Box3) return box3s_[node.box];
    // The margin keeps rounding of the extruded time range from separating boxes whose samples overlap.
    return extrude(box2s_[node.box], double(node.first) * path_.dt - margin_, double(node.end) * path_.dt + margin_);
}

}  // namespace mobb
