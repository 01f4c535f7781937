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

// The grid's free cells, found solid by solid, are those a test of every cell against every solid finds:
// rectangles, a triangle and a polygon across the world's edge, with a clearance that reaches across cells.
TEST(NavGrid, FreeCellsAreEveryCellTestedAgainstEverySolid) {
    World world{-3, -2, 17, 11, true, {}};
    world.obstacles.push_back(Polygon::rectangle(2.1, 1.3, 2.9, 7.7));
    world.obstacles.push_back(Polygon::rectangle(9.05, -5, 10.2, 0.4));
    world.obstacles.push_back({{{5, 5}, {8.3, 6.1}, {6.2, 9.4}}});
    world.obstacles.push_back({{{14, 8}, {20, 9}, {16, 13}, {13.5, 10.5}}});
    for (double clearance : {0.0, 0.45, 1.3}) {
        const NavGrid grid(world, clearance);
        const std::vector<Polygon> solids = world.solids();
        int blocked = 0;
        for (int ix = 0; ix < grid.nx; ++ix)
            for (int iy = 0; iy < grid.ny; ++iy) {
                const double x = grid.x0 + (ix + 0.5) * grid.cell, y = grid.y0 + (iy + 0.5) * grid.cell;
                bool hit = false;
                for (const Polygon& p : solids) hit = hit || disk_overlaps(p, x, y, clearance);
                ASSERT_EQ(grid.free[std::size_t(ix) * std::size_t(grid.ny) + std::size_t(iy)], hit ? 0 : 1)
                    << x << ", " << y << " clearance " << clearance;
                blocked += hit;
            }
        EXPECT_GT(blocked, 100);
    }
}

// Fields fit kFieldBytes: the cell is kNavCell for a few goals, and coarser as goals and ground grow -
// 4,000 goals over 200 x 200 m (SteerSuite's random.xml) at about 1.4 m.
TEST(NavGrid, CellsCoarsenToFitTheFieldsInMemory) {
    const World small{0, 0, 30, 40, true, {}};
    EXPECT_EQ(nav_cell(small, 60), kNavCell);
    const World big{-100, -100, 100, 100, true, {}};
    EXPECT_EQ(nav_cell(big, 2), kNavCell);
    const double cell = nav_cell(big, 4000);
    EXPECT_NEAR(cell, 1.39, 0.01);
    const double cells = std::ceil(200 / cell) * std::ceil(200 / cell);
    EXPECT_LE(cells * kBytesPerCell * 4000, kFieldBytes * 1.02);
}

}  // namespace
}  // namespace mobb::crowd
