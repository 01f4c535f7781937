#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "mobb/crowd/collision/broad_phase.h"
#include "mobb/util/worker_pool.h"

namespace mobb::crowd {
namespace {

TEST(BroadPhase, FindsOverlapsOfOtherOwnersOnly) {
    BroadPhase bp(2.0);
    bp.insert(0, 0, {0, 0, 1, 1, 0, 10});
    bp.insert(1, 1, {0.5, 0.5, 3, 3, 5, 20});
    bp.insert(2, 2, {10, 10, 11, 11, 0, 100});  // far away
    bp.insert(3, 3, {0, 0, 1, 1, 20, 30});      // later in time
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

// The crowd uses the id of an expired item again: its expired entry, left in a cell until something is
// next put there, is neither reported nor taken for the new item.
TEST(BroadPhase, ExpiredIdUsedAgain) {
    BroadPhase bp(4.0, 8, 8);
    bp.insert(7, 1, {1, 1, 2, 2, 0, 10});
    bp.expire(10);
    bp.insert(7, 2, {1.5, 1.5, 2.5, 2.5, 10, 30});
    std::vector<int> out;
    bp.query({0, 0, 3, 3, 0, 40}, 0, out);
    EXPECT_EQ(out, std::vector<int>({7}));
    bp.remove(7);
    bp.query({0, 0, 3, 3, 0, 40}, 0, out);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(bp.size(), 0u);
}

TEST(BroadPhase, RejectsBadCell) { EXPECT_THROW(BroadPhase(0.0), std::invalid_argument); }

// Queries from several threads at once (the crowd's parallel choice points) agree with a scan of all
// boxes; expired items are neither reported nor counted.
TEST(BroadPhase, ConcurrentQueriesAndExpiry) {
    BroadPhase bp(2.0, 20, 20);
    std::vector<SpaceTimeBox> boxes;
    for (int i = 0; i < 400; ++i) {
        const double x = double((i * 37) % 26) - 3, y = double((i * 53) % 26) - 3;  // some beyond the flat cells
        boxes.push_back({x, y, x + 0.5 + (i % 5), y + 0.5 + (i % 3), i % 7, 8 + i % 11});
        bp.insert(i, i % 9, boxes.back());
    }
    bp.expire(10);
    std::size_t live = 0;
    for (const SpaceTimeBox& b : boxes) live += b.f1 > 10;
    EXPECT_EQ(bp.size(), live);
    util::WorkerPool pool(4);
    std::vector<int> wrong(boxes.size(), 0);
    pool.for_each(boxes.size(), [&](std::size_t q, int) {
        SpaceTimeBox box = boxes[q];
        box.f0 = 10;
        std::vector<int> got, any, want;
        bp.query(box, int(q % 9), got);
        bp.query(box, int(q % 9), any, false);  // the same ids, each once, in any order
        std::sort(any.begin(), any.end());
        for (std::size_t i = 0; i < boxes.size(); ++i)
            if (int(i % 9) != int(q % 9) && boxes[i].f1 > 10 && boxes[i].overlaps(box)) want.push_back(int(i));
        wrong[q] = got != want || any != want;
    });
    EXPECT_EQ(std::count(wrong.begin(), wrong.end(), 1), 0);
    bp.insert(1000, 0, {0, 0, 1, 1, 0, 9});  // ends before the expiry frame: dropped
    std::vector<int> out;
    bp.query({0, 0, 1, 1, 10, 20}, 1, out);
    EXPECT_EQ(std::count(out.begin(), out.end(), 1000), 0);
}

// A frame's commits inserted at once by several workers give the grid that inserting them one by one
// gives: same answers to every query, same size, expired items still dropped.
TEST(BroadPhase, InsertAllMatchesInsertingOneByOne) {
    BroadPhase one(2.0, 20, 20), all(2.0, 20, 20);
    for (BroadPhase* bp : {&one, &all}) {
        bp->insert(0, 1, {1, 1, 3, 3, 0, 5});  // expires before the batch: its cells get compacted
        bp->expire(6);
    }
    std::vector<BroadPhase::Insertion> batch;
    for (int i = 1; i < 300; ++i) {
        const double x = double((i * 41) % 30) - 5, y = double((i * 29) % 30) - 5;  // some beyond the flat cells
        batch.push_back({i, i % 7, {x, y, x + 0.3 + (i % 6), y + 0.4 + (i % 4), 6, 7 + i % 13}});
    }
    batch.push_back({300, 2, {0, 0, 1, 1, 0, 6}});  // ends by the expiry frame: dropped by both
    for (const auto& it : batch) one.insert(it.id, it.owner, it.box);
    util::WorkerPool pool(3);
    all.insert_all(batch, pool);
    EXPECT_EQ(all.size(), one.size());
    EXPECT_EQ(all.size(), batch.size() - 1);
    int differing = 0;
    for (const auto& it : batch) {
        std::vector<int> a, b;
        one.query(it.box, it.owner, a);
        all.query(it.box, it.owner, b);
        differing += a != b;
    }
    EXPECT_EQ(differing, 0);
    std::vector<int> out;
    all.query({-10, -10, 40, 40, 0, 100}, -1, out);
    EXPECT_EQ(out.size(), batch.size() - 1);
}

// Inserts and removals (one by one and by batches), and expiry in random order, frame after frame, the
// boxes spanning several cells, some beyond the flat cells: every query answers as a scan of the items
// held (cells compacted lazily must never lose or revive an item).
// A random history's items: the broad phase, and what it should hold, for a scan to check it against.
class BroadPhaseHistory : public ::testing::Test {
protected:
    std::mt19937_64 rng;
    BroadPhase bp{2.0, 24, 24};
    util::WorkerPool pool{3};
    std::vector<SpaceTimeBox> boxes;
    std::vector<int> owners;
    std::vector<char> held;

    // A box from `frame` on, over a few cells, some beyond the flat ones.
    SpaceTimeBox random_box_from(std::int64_t frame) {
        std::uniform_real_distribution<double> pos(-6, 30), size(0, 7);
        const double x = pos(rng), y = pos(rng);
        const std::int64_t f0 = frame + std::int64_t(rng() % 5);
        return {x, y, x + size(rng), y + size(rng), f0, f0 + 1 + std::int64_t(rng() % 20)};
    }
    // What a query should answer: the held items of other owners overlapping `box`, ascending.
    std::vector<int> scan(const SpaceTimeBox& box, int owner) const {
        std::vector<int> out;
        for (std::size_t i = 0; i < boxes.size(); ++i)
            if (held[i] && owners[i] != owner && boxes[i].overlaps(box)) out.push_back(int(i));
        return out;
    }
};

TEST_F(BroadPhaseHistory, RandomHistoryMatchesBruteForce) {
    rng.seed(3);
    const auto random_box = [&](std::int64_t frame) {
        SpaceTimeBox box = random_box_from(frame);
        // Some end far on: the end counts keep frames up to 2^20 in an array, the others apart.
        const std::int64_t far = rng() % 2 ? 1000000 : 5000000;
        if (rng() % 10 == 0) box.f1 += far;
        return box;
    };
    int wrong = 0;
    for (std::int64_t frame = 0; frame < 120; ++frame) {
        bp.expire(frame);
        for (std::size_t i = 0; i < held.size(); ++i) held[i] = held[i] && boxes[i].f1 > frame;
        // Removals one by one, or with the batch's insertions (distinct ids, some not held). Every tenth
        // frame a large batch, often over BroadPhase::kFewItems, which the pool's workers share.
        const bool large = frame % 10 == 0;
        std::vector<int> gone;
        for (int k = int(rng() % (large ? 400 : 6)); k > 0 && !boxes.empty(); --k) {
            const int id = int(rng() % boxes.size());
            if (std::find(gone.begin(), gone.end(), id) != gone.end()) continue;
            if (rng() % 2)
                bp.remove(id);
            else
                gone.push_back(id);
            held[std::size_t(id)] = 0;
        }
        std::vector<BroadPhase::Insertion> batch;
        for (int k = int(rng() % (large ? 800 : 12)); k > 0; --k) {
            const int id = int(boxes.size());
            boxes.push_back(random_box(frame));
            owners.push_back(int(rng() % 6));
            held.push_back(1);
            if (rng() % 2)
                bp.insert(id, owners.back(), boxes.back());
            else
                batch.push_back({id, owners.back(), boxes.back()});
        }
        if (rng() % 2) {
            // Ids inserted again in the same update, held or just removed: each replaces its item.
            const std::size_t fresh = batch.size();
            for (int k = int(rng() % (large ? 40 : 3)); k > 0 && boxes.size() > fresh; --k) {
                const int id = int(rng() % (boxes.size() - fresh));
                const auto same = [id](const BroadPhase::Insertion& in) { return in.id == id; };
                if (std::any_of(batch.begin(), batch.end(), same)) continue;
                boxes[std::size_t(id)] = random_box(frame);
                held[std::size_t(id)] = 1;
                batch.push_back({id, owners[std::size_t(id)], boxes[std::size_t(id)]});
            }
            bp.update(gone, batch, pool);
        } else {
            bp.insert_all(batch, pool), bp.update(gone, {}, pool);
        }
        if (rng() % 3 == 0 && !boxes.empty()) {  // an id inserted again replaces its item
            const int id = int(rng() % boxes.size());
            boxes[std::size_t(id)] = random_box(frame);
            bp.insert(id, owners[std::size_t(id)], boxes[std::size_t(id)]);
            held[std::size_t(id)] = 1;
        }
        std::size_t live = 0;
        for (std::size_t i = 0; i < held.size(); ++i) {
            live += std::size_t(held[i]);
            wrong += bp.holds(int(i)) != bool(held[i]);
        }
        wrong += bp.size() != live;
        for (int q = 0; q < 20; ++q) {
            const SpaceTimeBox box = random_box(frame);
            const int owner = int(rng() % 7);
            std::vector<int> got;
            bp.query(box, owner, got);
            wrong += got != scan(box, owner);
        }
    }
    for (const std::int64_t frame : {1000200, 5000200}) {  // past the far ends: counted apart, then in the array
        bp.expire(frame);
        std::size_t live = 0;
        for (std::size_t i = 0; i < boxes.size(); ++i) live += std::size_t(held[i] && boxes[i].f1 > frame);
        wrong += bp.size() != live;
        if (frame == 1000200) {
            EXPECT_GT(live, 0u);  // the far ones are left
        }
    }
    EXPECT_EQ(wrong, 0);
}

// Items held for ever stay until the end of time, which drops them too; far beyond the flat cells,
// cells whose indices share their low 32 bits do not confuse the queries.
TEST(BroadPhase, ForeverItemsAndFarCells) {
    constexpr auto kNever = std::numeric_limits<std::int64_t>::max();
    BroadPhase bp(1.0, 10, 10);
    bp.insert(0, 0, {1, 1, 2, 2, 0, kNever});
    bp.insert(1, 0, {1, 1, 2, 2, 0, 50});
    const double far = std::ldexp(1.0, 32);  // cell 2^32: its low bits are those of cell 0
    bp.insert(2, 0, {far + 0.5, 0.5, far + 2.5, 1.5, 0, kNever});
    std::vector<int> out;
    bp.expire(1000);
    EXPECT_EQ(bp.size(), 2u);
    bp.query({0, 0, 3, 3, 1000, 1001}, 1, out);
    EXPECT_EQ(out, std::vector<int>({0}));
    bp.query({far - 0.5, 0, far + 3, 2, 1000, 1001}, 1, out);
    EXPECT_EQ(out, std::vector<int>({2}));
    bp.query({far + 1.2, 0, far + 1.3, 2, 1000, 1001}, 1, out);
    EXPECT_EQ(out, std::vector<int>({2}));
    bp.expire(kNever);
    EXPECT_EQ(bp.size(), 0u);
    bp.query({0, 0, 3, 3, 0, kNever}, 1, out);
    EXPECT_TRUE(out.empty());
    bp.query({far - 0.5, 0, far + 3, 2, 0, kNever}, 1, out);
    EXPECT_TRUE(out.empty());
    bp.insert(3, 0, {1, 1, 2, 2, 0, kNever});  // ends by the expiry frame: dropped
    EXPECT_EQ(bp.size(), 0u);
}

// The crowd's way (commit.cpp): removals and insertions staged by the pool's workers as their lists grow,
// in two parts a frame, then entered at once. Nothing is entered before apply_staged(): holds(), size()
// and queries answer as before; after it every query answers as a scan of the items held - expired ids used
// again among them, some still in their cells.
TEST_F(BroadPhaseHistory, StagedItemsEnterOnlyWhenApplied) {
    rng.seed(11);
    const auto answers = [&](std::uint64_t seed) {  // a fixed set of queries' answers
        std::mt19937_64 q{seed};
        std::vector<std::vector<int>> out(20);
        for (std::vector<int>& o : out) {
            const double x = double(q() % 30) - 3, y = double(q() % 30) - 3;
            const auto f0 = std::int64_t(q() % 130);
            bp.query({x, y, x + 5, y + 5, f0, f0 + 10}, int(q() % 7), o);
        }
        return out;
    };
    int wrong = 0, staged_items = 0;
    for (std::int64_t frame = 0; frame < 120; ++frame) {
        bp.expire(frame);
        for (std::size_t i = 0; i < held.size(); ++i) held[i] = held[i] && boxes[i].f1 > frame;
        std::vector<int> removed;
        std::vector<BroadPhase::Insertion> inserted;
        for (std::size_t id = 0; id < boxes.size(); ++id) {  // removed, replaced, or (not held) used again
            const std::uint64_t r = rng() % 16;
            if (held[id] && r < 2) removed.push_back(int(id));
            if ((held[id] && r == 2) || (!held[id] && r < 2))
                inserted.push_back({int(id), owners[id], random_box_from(frame)});
        }
        for (int k = int(rng() % 90); k > 0; --k) {
            inserted.push_back({int(boxes.size()), int(rng() % 6), random_box_from(frame)});
            boxes.push_back({});
            owners.push_back(inserted.back().owner);
            held.push_back(0);
        }
        const std::vector<std::vector<int>> before = answers(std::uint64_t(frame));
        const std::size_t live = bp.size();
        const std::size_t nr = removed.size() / 2, ni = inserted.size() / 2;  // two parts, as two runs
        bp.stage(nr, ni);
        pool.for_each(nr + ni, [&](std::size_t k, int) {
            if (k < nr) return bp.stage_removed(k, removed[k]);
            bp.stage_inserted(k - nr, inserted[k - nr]);
        });
        bp.stage(removed.size(), inserted.size());
        pool.for_each(removed.size() - nr + inserted.size() - ni, [&](std::size_t k, int) {
            if (k < removed.size() - nr) return bp.stage_removed(nr + k, removed[nr + k]);
            bp.stage_inserted(ni + k - (removed.size() - nr), inserted[ni + k - (removed.size() - nr)]);
        });
        wrong += answers(std::uint64_t(frame)) != before || bp.size() != live;
        for (int id : removed) wrong += !bp.holds(id);
        bp.apply_staged(pool);
        staged_items += int(removed.size() + inserted.size());
        for (int id : removed) held[std::size_t(id)] = 0;
        for (const BroadPhase::Insertion& in : inserted) {
            boxes[std::size_t(in.id)] = in.box;
            held[std::size_t(in.id)] = in.box.f1 > frame;
        }
        std::size_t count = 0;
        for (std::size_t i = 0; i < held.size(); ++i) {
            count += std::size_t(held[i]);
            wrong += bp.holds(int(i)) != bool(held[i]);
        }
        wrong += bp.size() != count;
        std::mt19937_64 q{std::uint64_t(frame)};
        for (const std::vector<int>& got : answers(std::uint64_t(frame))) {
            const double x = double(q() % 30) - 3, y = double(q() % 30) - 3;
            const auto f0 = std::int64_t(q() % 130);
            const SpaceTimeBox box{x, y, x + 5, y + 5, f0, f0 + 10};
            wrong += got != scan(box, int(q() % 7));
        }
    }
    EXPECT_GT(staged_items, 5000);
    EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace mobb::crowd
