// The navigation field kept up to date as agents settle (NavField::block) against building it again
// on the blocked grid: the same distances everywhere, including cells cut off and cells behind a gap
// closed.
#include <gtest/gtest.h>

#include <cmath>

#include "policy/nav_field.h"

namespace mobb::crowd {
namespace {

// Every cell centre's distance, both unreachable or equal to rounding.
void expect_same(const NavGrid& grid, const NavField& kept, const NavField& built, int& compared) {
    for (int ix = 0; ix < grid.nx; ++ix)
        for (int iy = 0; iy < grid.ny; ++iy) {
            const double x = grid.x0 + (ix + 0.5) * grid.cell, y = grid.y0 + (iy + 0.5) * grid.cell;
            const double a = kept.distance(x, y), b = built.distance(x, y);
            if (b >= NavField::kUnreachable) {
                ASSERT_GE(a, NavField::kUnreachable) << x << ", " << y;
                continue;
            }
            ASSERT_NEAR(a, b, 1e-9) << x << ", " << y;
            ++compared;
        }
}

TEST(NavField, BlockingDisksGivesTheFieldBuiltAgain) {
    World world{0, 0, 20, 12, true, {}};
    world.obstacles.push_back(Polygon::rectangle(8, 0, 9, 9));  // a wall with a 3 m gap at its top
    NavGrid grid(world, 0.45);
    const std::array<double, 2> goal{16, 3};
    NavField field(grid, goal);
    // A disk on the far side, one next to the goal, two closing the gap (the left side cut off), and one
    // in the part cut off.
    const double disks[][3] = {{14, 8, 0.5}, {16.9, 3.2, 0.48}, {8.5, 10, 0.6}, {8.5, 11.4, 0.6}, {3, 3, 0.5}};
    int compared = 0;
    for (const auto& d : disks) {
        grid.block_disk(d[0], d[1], d[2]);
        field.block(grid);
        expect_same(grid, field, NavField(grid, goal), compared);
    }
    EXPECT_GT(compared, 1000);
    EXPECT_GE(field.distance(2, 2), NavField::kUnreachable);  // behind the closed gap
    EXPECT_LT(field.distance(12, 2), 10.0);
}

}  // namespace
}  // namespace mobb::crowd
