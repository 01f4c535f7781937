#include <gtest/gtest.h>

#include "mobb/crowd/broad_phase.h"

namespace mobb::crowd {
namespace {

TEST(BroadPhase, FindsOverlapsOfOtherOwnersOnly) {
    BroadPhase bp(2.0);
    bp.insert(0, 0, {0, 0, 1, 1, 0, 10});
    bp.insert(1, 1, {0.5, 0.5, 3, 3, 5, 20});
    bp.insert(2, 2, {10, 10, 11, 11, 0, 100});   // far away
    bp.insert(3, 3, {0, 0, 1, 1, 20, 30});       // later in time
    std::vector<int> out;
    bp.query({0, 0, 2, 2, 0, 20}, 0, out);
    EXPECT_EQ(out, std::vector<int>({1}));
    bp.query({0, 0, 2, 2, 0, 20}, 9, out);
    EXPECT_EQ(out, std::vector<int>({0, 1}));
    bp.remove(1);
    bp.query({0, 0, 2, 2, 0, 20}, 9, out);
    EXPECT_EQ(out, std::vector<int>({0}));
    EXPECT_EQ(bp.size(), 3u);
}

TEST(BroadPhase, NegativeCoordinatesAndBigBoxes) {
    BroadPhase bp(1.0);
    bp.insert(0, 0, {-5.5, -3.2, 4.1, -2.9, 0, 1});
    std::vector<int> out;
    bp.query({-0.1, -3.0, 0.1, -2.95, 0, 1}, 1, out);
    EXPECT_EQ(out, std::vector<int>({0}));
    bp.query({-0.1, -2.0, 0.1, -1.0, 0, 1}, 1, out);
    EXPECT_TRUE(out.empty());
}

TEST(BroadPhase, RejectsBadCell) { EXPECT_THROW(BroadPhase(0.0), std::invalid_argument); }

}  // namespace
}  // namespace mobb::crowd
