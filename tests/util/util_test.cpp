// The utilities below the crowd: the worker pool, the task queue and the median.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "mobb/util/median.h"
#include "mobb/util/task_queue.h"
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
        // A loop started from inside another is refused, and the outer one still runs every index.
        std::atomic<int> refused{0}, ran{0};
        pool.for_each(8, [&](std::size_t, int) {
            ++ran;
            try {
                pool.for_each(4, [](std::size_t, int) {});
            } catch (const std::logic_error&) {
                ++refused;
            }
        });
        EXPECT_EQ(ran.load(), 8);
        EXPECT_EQ(refused.load(), 8);
    }
    EXPECT_THROW(WorkerPool(0), std::invalid_argument);
}

// Many small jobs back to back, some after the workers went to sleep: each index runs once per job, and no
// worker joins a job after the next one was set up (a late one would run an index of the wrong job twice).
TEST(WorkerPool, BackToBackJobsRunEachIndexOnce) {
    WorkerPool pool(3);
    std::vector<std::atomic<int>> runs(9);
    for (int job = 0; job < 20000; ++job) {
        const std::size_t n = 2 + std::size_t(job % 8);
        for (std::size_t i = 0; i < n; ++i) runs[i] = 0;
        pool.for_each(n, [&](std::size_t i, int) { ++runs[i]; });
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(runs[i].load(), 1) << "job " << job << " index " << i;
        if (job % 5000 == 4999) std::this_thread::sleep_for(std::chrono::milliseconds(10));  // past the spin
    }
}

// Tasks run one at a time in the order posted, off the posting thread; a full queue makes post() wait
// (the tasks waiting never exceed its room); the first task that throws stops those after it, and the
// poster hears of it; the queue's end runs what still waits.
TEST(TaskQueue, RunsTasksInOrderAndReportsTheFirstError) {
    std::vector<int> ran;
    std::atomic<int> waiting{0}, most{0};
    const auto caller = std::this_thread::get_id();
    {
        TaskQueue queue(3);
        for (int k = 0; k < 50; ++k) {
            most = std::max(most.load(), ++waiting);
            queue.post([&, k] {
                --waiting;
                std::this_thread::sleep_for(std::chrono::microseconds(k % 7 == 0 ? 2000 : 0));
                EXPECT_NE(std::this_thread::get_id(), caller);
                ran.push_back(k);
            });
        }
        queue.drain();
        ASSERT_EQ(ran.size(), 50u);
        for (int k = 0; k < 50; ++k) EXPECT_EQ(ran[std::size_t(k)], k);
        EXPECT_LE(most.load(), 5);  // 3 waiting, one taken but not begun, the one being posted
        for (int k = 50; k < 60; ++k) queue.post([&, k] { ran.push_back(k); });
    }  // the end runs them
    EXPECT_EQ(ran.size(), 60u);

    TaskQueue queue(2);
    queue.post([] { throw std::runtime_error("first"); });
    queue.post([] { throw std::runtime_error("second"); });  // may already be refused
    bool later = false;
    try {
        for (int k = 0; k < 100; ++k) queue.post([&] { later = true; });
        queue.drain();
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "first");
    }
    EXPECT_FALSE(later);
    EXPECT_THROW(queue.drain(), std::runtime_error);
    EXPECT_THROW(TaskQueue(0), std::invalid_argument);
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
