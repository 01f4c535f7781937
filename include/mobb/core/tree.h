// MOBB, UMOBB, hybrid and 1-level trees: built once per path, queried under any placement.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mobb/core/fit.h"
#include "mobb/core/obb.h"
#include "mobb/core/path.h"

namespace mobb {

/// Tree kinds of the paper (sections 3-5, Table 1).
enum class TreeType : std::uint8_t {
    Mobb,     ///< 2D boxes extruded in time at every node
    Umobb,    ///< 3D space-time boxes at every node
    Hybrid1,  ///< MOBB root, UMOBB below
    Hybrid2,  ///< UMOBB root, MOBB below
    Mobb1,    ///< "1 level": MOBB root only, then binary search in time and sample tests
    Umobb1,   ///< "1 level": UMOBB root only
};

/// The tree-type table: each type's name on the command line and in scene files, and its label in
/// the benchmark tables and the viewer (the paper's words).
struct TreeTypeName {
    TreeType type;
    const char* name;   ///< "mobb", "umobb", "hybrid1", "hybrid2", "mobb1", "umobb1"
    const char* label;  ///< "MOBB", "UMOBB", "Hybrid 1", "Hybrid 2", "MOBB 1 level", "UMOBB 1 level"
};
/// Every tree type, in TreeType order.
inline constexpr TreeTypeName kTreeTypes[] = {
    {TreeType::Mobb, "mobb", "MOBB"},           {TreeType::Umobb, "umobb", "UMOBB"},
    {TreeType::Hybrid1, "hybrid1", "Hybrid 1"}, {TreeType::Hybrid2, "hybrid2", "Hybrid 2"},
    {TreeType::Mobb1, "mobb1", "MOBB 1 level"}, {TreeType::Umobb1, "umobb1", "UMOBB 1 level"},
};
inline constexpr int kTreeTypeCount = int(sizeof kTreeTypes / sizeof kTreeTypes[0]);

/// The command-line name and the label of a type (kTreeTypes).
const char* to_string(TreeType type);
const char* label(TreeType type);
/// The type of a command-line name; throws std::invalid_argument naming the valid ones.
TreeType parse_tree_type(const std::string& name);
/// "mobb, umobb, hybrid1, hybrid2, mobb1, umobb1", for messages.
std::string tree_type_names();

struct TreeOptions {
    TreeType type = TreeType::Mobb;
    int n_min = 10;                ///< leaves hold at most n_min samples (paper 3.1); >= 1
    AxisFit fit = AxisFit::Chord;  ///< MOBB axis choice
};
/// The options of a type name, n_min and an axis fit name, as the command line and the Python module
/// take them. Throws std::invalid_argument for an unknown name (n_min is checked by Tree::build).
TreeOptions parse_tree_options(const std::string& type, int n_min, const std::string& fit);

enum class BoxKind : std::uint8_t { Box2, Box3 };

/// One node of a flat tree. Children, if any, are nodes `child` and `child + 1`, splitting the
/// node's samples into two equal halves in time (paper 3).
struct Node {
    std::uint32_t first = 0, end = 0;  ///< samples [first, end)
    std::int32_t child = -1;           ///< -1 for a leaf
    std::uint32_t box = 0;             ///< index into box2s() or box3s(), by kind
    BoxKind kind = BoxKind::Box2;
    std::uint8_t level = 0;  ///< 0 at the root

    bool leaf() const { return child < 0; }
};

class Tree {
public:
    /// Throws std::invalid_argument for an empty or invalid path or n_min < 1.
    static Tree build(Path path, const TreeOptions& options = {});

    const Path& path() const { return path_; }
    const TreeOptions& options() const { return options_; }
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<Obb2>& box2s() const { return box2s_; }
    const std::vector<Obb3>& box3s() const { return box3s_; }
    const Node& root() const { return nodes_.front(); }
    int depth() const { return depth_; }  ///< number of levels

    /// The node's box as a 3D space-time box in the clip's local frame (2D boxes extruded).
    Obb3 box3(const Node& node) const;

private:
    void fill(int index, std::uint32_t first, std::uint32_t end, int level);

    Path path_;
    TreeOptions options_;
    std::vector<Node> nodes_;
    std::vector<Obb2> box2s_;
    std::vector<Obb3> box3s_;
    int depth_ = 0;
    double margin_ = 0;
};

/// Per-level statistics of a tree, for `mobb tree` and the viewer's fit panel.
struct LevelStats {
    int level = 0;
    int nodes = 0;
    int box2 = 0, box3 = 0;   ///< nodes of each kind
    double mean_area = 0;     ///< mean area (m^2) of the level's 2D boxes
    double area_ratio = 0;    ///< mean of 2D box area over the area of the union of its disks (>= 1)
    double mean_volume = 0;   ///< mean space-time volume (m^2 s) of every node, 2D boxes extruded
    double volume_ratio = 0;  ///< mean of box volume over the volume of its sample cylinders (>= 1)
};
std::vector<LevelStats> level_stats(const Tree& tree);

/// Tightness of one node's box: its space-time volume (2D boxes extruded over the node's time range)
/// over the volume of its sample cylinders, >= 1 (1 would be a box as tight as the disks themselves).
double volume_ratio(const Tree& tree, const Node& node);

/// Every sample cylinder lies inside the box of every node that holds it (tolerance in metres).
bool all_samples_contained(const Tree& tree, double tol = 1e-9);

}  // namespace mobb
