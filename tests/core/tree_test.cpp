#include <gtest/gtest.h>

#include <random>

#include "mobb/core/tree.h"
#include "random_paths.h"

namespace mobb {
namespace {

constexpr TreeType kTypes[] = {TreeType::Mobb,    TreeType::Umobb, TreeType::Hybrid1,
                               TreeType::Hybrid2, TreeType::Mobb1, TreeType::Umobb1};

// Children split their parent's samples into two halves in time; leaves hold at most n_min.
void expect_well_formed(const Tree& tree) {
    const auto& nodes = tree.nodes();
    ASSERT_FALSE(nodes.empty());
    EXPECT_EQ(nodes[0].first, 0u);
    EXPECT_EQ(nodes[0].end, tree.path().size());
    std::size_t leaf_samples = 0;
    const bool one_level = tree.options().type == TreeType::Mobb1 || tree.options().type == TreeType::Umobb1;
    for (const Node& n : nodes) {
        if (n.leaf()) {
            leaf_samples += n.end - n.first;
            if (!one_level) {
                EXPECT_LE(n.end - n.first, std::uint32_t(tree.options().n_min));
            }
            continue;
        }
        const Node& l = nodes[std::size_t(n.child)];
        const Node& r = nodes[std::size_t(n.child) + 1];
        EXPECT_EQ(l.first, n.first);
        EXPECT_EQ(l.end, r.first);
        EXPECT_EQ(r.end, n.end);
        EXPECT_LE(r.end - r.first - (l.end - l.first), 1u);
        EXPECT_EQ(l.level, n.level + 1);
    }
    EXPECT_EQ(leaf_samples, tree.path().size());
}

TEST(TreeTest, EveryTypeIsWellFormedAndContainsEveryCylinder) {
    std::mt19937_64 rng(11);
    for (int n : {1, 2, 9, 10, 11, 64, 301, 1376}) {
        const Path p = test::random_walk(rng, n);
        for (TreeType type : kTypes)
            for (int n_min : {1, 3, 10}) {
                const Tree tree = Tree::build(p, {type, n_min});
                SCOPED_TRACE(std::string(to_string(type)) + " n=" + std::to_string(n));
                expect_well_formed(tree);
                EXPECT_TRUE(all_samples_contained(tree));
            }
    }
}

TEST(TreeTest, DegeneratePathsBuild) {
    for (const Path& p : {test::standing_still(1), test::standing_still(100), test::circle(200)})
        for (TreeType type : kTypes) {
            const Tree tree = Tree::build(p, {type, 10});
            expect_well_formed(tree);
            EXPECT_TRUE(all_samples_contained(tree));
        }
}

TEST(TreeTest, NodeKindsFollowTheTreeType) {
    std::mt19937_64 rng(12);
    const Path p = test::random_walk(rng, 400);
    auto kinds = [&](TreeType t, int level) {
        int k2 = 0, k3 = 0;
        const Tree tree = Tree::build(p, {t});
        for (const Node& n : tree.nodes())
            if (n.level == level) (n.kind == BoxKind::Box2 ? k2 : k3)++;
        return std::make_pair(k2, k3);
    };
    EXPECT_EQ(kinds(TreeType::Mobb, 0), std::make_pair(1, 0));
    EXPECT_EQ(kinds(TreeType::Mobb, 2), std::make_pair(4, 0));
    EXPECT_EQ(kinds(TreeType::Umobb, 0), std::make_pair(0, 1));
    EXPECT_EQ(kinds(TreeType::Umobb, 2), std::make_pair(0, 4));
    EXPECT_EQ(kinds(TreeType::Hybrid1, 0), std::make_pair(1, 0));
    EXPECT_EQ(kinds(TreeType::Hybrid1, 1), std::make_pair(0, 2));
    EXPECT_EQ(kinds(TreeType::Hybrid2, 0), std::make_pair(0, 1));
    EXPECT_EQ(kinds(TreeType::Hybrid2, 1), std::make_pair(2, 0));
    EXPECT_EQ(Tree::build(p, {TreeType::Mobb1}).nodes().size(), 1u);
    EXPECT_EQ(Tree::build(p, {TreeType::Umobb1}).nodes().size(), 1u);
}

TEST(TreeTest, DepthFollowsNMin) {
    Path p = test::standing_still(1376);
    EXPECT_EQ(Tree::build(p, {TreeType::Mobb, 10}).depth(), 9);  // 1376 / 2^8 = 5.4 <= 10 < 10.75
    EXPECT_EQ(Tree::build(p, {TreeType::Mobb, 1}).depth(), 12);  // ceil(log2 1376) + 1
}

TEST(TreeTest, LevelStatsCountNodesAndAreAtLeastTight) {
    std::mt19937_64 rng(13);
    const Tree tree = Tree::build(test::random_walk(rng, 640), {TreeType::Mobb, 10});
    const auto levels = level_stats(tree);
    ASSERT_EQ(int(levels.size()), tree.depth());
    for (std::size_t l = 0; l < levels.size(); ++l) {
        EXPECT_EQ(levels[l].nodes, 1 << l);
        EXPECT_GE(levels[l].area_ratio, 0.99);
        EXPECT_GE(levels[l].volume_ratio, 1.0);
        if (l) {
            EXPECT_LT(levels[l].mean_area, levels[l - 1].mean_area);
        }
    }
}

/// volume_ratio() per node is at least 1 (boxes contain their cylinders), and its mean per level is
/// level_stats()' volume_ratio; a standing character's upright box is exactly as tight as its disks
/// squared off: 4 / pi.
TEST(TreeTest, VolumeRatioPerNode) {
    std::mt19937_64 rng(14);
    const Tree tree = Tree::build(test::random_walk(rng, 640), {TreeType::Umobb, 10});
    const auto levels = level_stats(tree);
    std::vector<double> sum(levels.size(), 0.0);
    for (const Node& n : tree.nodes()) {
        const double r = volume_ratio(tree, n);
        EXPECT_GE(r, 1.0);
        sum[n.level] += r;
    }
    for (std::size_t l = 0; l < levels.size(); ++l)
        EXPECT_NEAR(sum[l] / levels[l].nodes, levels[l].volume_ratio, 1e-9 * levels[l].volume_ratio);
    const Tree still = Tree::build(test::standing_still(40, 0.3), {TreeType::Mobb, 10});
    EXPECT_NEAR(volume_ratio(still, still.root()), 4.0 / 3.141592653589793, 1e-6);
}

TEST(TreeTest, RejectsBadInput) {
    EXPECT_THROW(Tree::build(Path{}), std::invalid_argument);
    EXPECT_THROW(Tree::build(test::standing_still(3), {TreeType::Mobb, 0}), std::invalid_argument);
    Path bad = test::standing_still(3);
    bad.samples[1].x = NAN;
    EXPECT_THROW(Tree::build(bad), std::invalid_argument);
    bad = test::standing_still(3);
    bad.dt = 0;
    EXPECT_THROW(Tree::build(bad), std::invalid_argument);
    EXPECT_THROW(parse_tree_type("obb"), std::invalid_argument);
    for (TreeType t : kTypes) EXPECT_EQ(parse_tree_type(to_string(t)), t);
}

TEST(TreeTest, ParsesOptionNames) {
    const TreeOptions o = parse_tree_options("hybrid2", 7, "pca");
    EXPECT_EQ(o.type, TreeType::Hybrid2);
    EXPECT_EQ(o.n_min, 7);
    EXPECT_EQ(o.fit, AxisFit::Pca);
    EXPECT_EQ(parse_tree_options("umobb1", 10, "chord").fit, AxisFit::Chord);
    EXPECT_THROW(parse_tree_options("mobb", 10, "svd"), std::invalid_argument);
    EXPECT_THROW(parse_tree_options("box", 10, "chord"), std::invalid_argument);
}

}  // namespace
}  // namespace mobb
