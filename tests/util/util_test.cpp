// The utilities below the crowd: the worker pool and the median.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "mobb/util/median.h"
#include "mobb/util/worker_pool.h"

namespace mobb::util {
namespace {

TEST(WorkerPool, RunsEveryIndexOnceAndRethrowsTheLowestError) {
    for (int threads : {1, 2, 5}) {
        WorkerPool pool(threads);
        EXPECT_EQ(pool.size(), threads);
        for (std::size_t grain : {1u, 3u, 64u}) {
            std::vector<std::atomic<int>> seen(1000);
            std::vector<int> worker(seen.size(), -1);
            pool.for_each(
                seen.size(),
                [&](std::size_t i, int w) {
                    ++seen[i];
                    worker[i] = w;
                },
                grain);
            for (std::size_t i = 0; i < seen.size(); ++i) {
                ASSERT_EQ(seen[i].load(), 1) << i;
                ASSERT_TRUE(worker[i] >= 0 && worker[i] < threads);
            }
        }
        try {
            pool.for_each(100, [](std::size_t i, int) {
                if (i % 10 == 7) throw std::runtime_error(std::to_string(i));
            });
            ADD_FAILURE() << "no exception";
        } catch (const std::runtime_error& e) {
            EXPECT_STREQ(e.what(), "7");
        }
        pool.for_each(0, [](std::size_t, int) { ADD_FAILURE(); });
    }
    EXPECT_THROW(WorkerPool(0), std::invalid_argument);
}

TEST(Median, MiddleValueOrMeanOfTheTwoMiddle) {
    EXPECT_EQ(median({}), 0.0);
    EXPECT_EQ(median({3.0}), 3.0);
    EXPECT_EQ(median({5.0, 1.0, 3.0}), 3.0);
    EXPECT_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
    EXPECT_EQ(median({2.0, 2.0, 9.0, -1.0}), 2.0);
}

}  // namespace
}  // namespace mobb::util
