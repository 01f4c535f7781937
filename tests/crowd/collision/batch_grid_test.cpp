// The grid of a frame's plans (src/crowd/collision/batch_grid.h), which tells a choice point whether a plan
// committed before it could change its evaluation: its answers equal a scan of every box added.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "collision/batch_grid.h"
#include "mobb/util/worker_pool.h"

namespace mobb::crowd {
namespace {

// Groups of a few boxes by increasing index, some reaching past the grid's rectangle (they land in its
// border cells), some empty; queries over every range of indices.
TEST(BatchGrid, AnswersAsAScanOfItsBoxes) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> pos(-10, 60), size(0, 12);
    const auto random_box = [&] {
        const double x = pos(rng), y = pos(rng);
        const auto f0 = std::int64_t(rng() % 30);
        return SpaceTimeBox{x, y, x + size(rng), y + size(rng), f0, f0 + 1 + std::int64_t(rng() % 30)};
    };
    BatchGrid grid(4.0, 0, 0, 50, 50);
    for (int round = 0; round < 2; ++round) {  // the second after clear(): nothing of the first is left
        grid.clear();
        std::vector<std::vector<SpaceTimeBox>> groups(40);
        for (int index = 0; index < int(groups.size()); ++index) {
            for (int k = int(rng() % 4); k > 0; --k) groups[std::size_t(index)].push_back(random_box());
            grid.add(index, groups[std::size_t(index)]);
        }
        int wrong = 0, hits = 0;
        for (int q = 0; q < 300; ++q) {
            const SpaceTimeBox box = random_box();
            const int from = int(rng() % 40), below = from + int(rng() % std::uint64_t(41 - from));
            int last = -1;
            for (int index = from; index < below; ++index)
                for (const SpaceTimeBox& b : groups[std::size_t(index)])
                    if (b.overlaps(box)) last = index;
            hits += last >= 0;
            wrong += grid.any_between(box, from, below) != (last >= 0);
            wrong += grid.last_between(box, from, below) != last;
        }
        EXPECT_EQ(wrong, 0);
        EXPECT_GT(hits, 30);  // the test meets overlaps, not only misses
        EXPECT_LT(hits, 270);
    }
}

// fill() by three workers answers as add() of each in turn: the same groups, every cell's in index order
// (last_between reads them backwards), over enough groups that the workers share them.
TEST(BatchGrid, FillAnswersAsAddingInTurn) {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> pos(-10, 160), size(0, 9);
    const auto random_box = [&] {
        const double x = pos(rng), y = pos(rng);
        const auto f0 = std::int64_t(rng() % 30);
        return SpaceTimeBox{x, y, x + size(rng), y + size(rng), f0, f0 + 1 + std::int64_t(rng() % 30)};
    };
    std::vector<std::vector<SpaceTimeBox>> groups(600);
    for (std::vector<SpaceTimeBox>& g : groups)
        for (int k = int(rng() % 4); k > 0; --k) g.push_back(random_box());
    BatchGrid added(4.0, 0, 0, 150, 150), filled(4.0, 0, 0, 150, 150);
    for (std::size_t i = 0; i < groups.size(); ++i) added.add(int(i), groups[i]);
    util::WorkerPool pool(3);
    const auto span = [&](std::size_t i) {
        return BatchGrid::Span{groups[i].data(), groups[i].data() + groups[i].size()};
    };
    for (int round = 0; round < 2; ++round) {  // the second after clear()
        filled.clear();
        filled.fill(groups.size(), span, pool);
        EXPECT_EQ(filled.last_index(), added.last_index());
        int wrong = 0, hits = 0;
        for (int q = 0; q < 2000; ++q) {
            const SpaceTimeBox box = random_box();
            const int from = int(rng() % 600), below = from + int(rng() % std::uint64_t(601 - from));
            const int last = added.last_between(box, from, below);
            hits += last >= 0;
            wrong += filled.last_between(box, from, below) != last;
            wrong += filled.any_between(box, from, below) != added.any_between(box, from, below);
        }
        EXPECT_EQ(wrong, 0);
        EXPECT_GT(hits, 200);  // overlaps met, not only misses
    }
}

}  // namespace
}  // namespace mobb::crowd
