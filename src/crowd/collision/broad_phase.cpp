#include "mobb/crowd/collision/broad_phase.h"

#include "mobb/core/assert.h"
#include "mobb/util/worker_pool.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mobb::crowd {

BroadPhase::BroadPhase(double cell) : inv_cell_(1 / cell) {
    if (!(cell > 0)) throw std::invalid_argument("broad phase: cell size must be positive");
}

BroadPhase::BroadPhase(double cell, double width, double height) : BroadPhase(cell, 0, 0, width, height) {}

BroadPhase::BroadPhase(double cell, double x0, double y0, double x1, double y1) : BroadPhase(cell) {
    if (!(x1 >= x0) || !(y1 >= y0)) throw std::invalid_argument("broad phase: negative world size");
    x0_ = x0, y0_ = y0;
    // A huge world would make a huge array: then every cell is hashed.
    if (((x1 - x0) / cell + 1) * ((y1 - y0) / cell + 1) > double(kMaxFlatCells)) return;
    nx_ = index_x(x1) + 1;
    ny_ = index_y(y1) + 1;
    flat_.resize(std::size_t(nx_ * ny_));
}

BroadPhase::Cell& BroadPhase::cell(std::int64_t ix, std::int64_t iy) {
    if (flat(ix, iy)) return flat_[std::size_t(ix * ny_ + iy)];
    return hashed_[key(ix, iy)];
}

const BroadPhase::Cell* BroadPhase::find(std::int64_t ix, std::int64_t iy) const {
    if (flat(ix, iy)) return &flat_[std::size_t(ix * ny_ + iy)];
    const auto it = hashed_.find(key(ix, iy));
    return it == hashed_.end() ? nullptr : &it->second;
}

template <class F>
void BroadPhase::cells(const SpaceTimeBox& box, F&& f) const {
    const std::int64_t ix0 = index_x(box.x0), ix1 = index_x(box.x1), iy0 = index_y(box.y0), iy1 = index_y(box.y1);
    for (std::int64_t ix = ix0; ix <= ix1; ++ix)
        for (std::int64_t iy = iy0; iy <= iy1; ++iy) f(ix, iy);
}

// The item table's part of an insertion; false when the item is gone already.
bool BroadPhase::enroll(int id, int owner, const SpaceTimeBox& box) {
    if (id < 0) throw std::invalid_argument("broad phase: negative id");
    // Doubling: ids come one more at a time, and resize() to each would take its slow path each time.
    if (std::size_t(id) >= items_.size()) items_.resize(std::max(std::size_t(id) + 1, 2 * items_.size()));
    remove(id);  // when held
    if (box.f1 <= expired_) return false;
    items_[std::size_t(id)] = {box, owner, true};
    ++live_;
    count_end(box.f1, +1);
    return true;
}

void BroadPhase::count_end_rarely(std::int64_t f1, int delta) {
    if (f1 < 0 || f1 >= kFlatEnds) {
        const auto it = ending_.try_emplace(f1, 0).first;
        if ((it->second += std::size_t(delta)) == 0) ending_.erase(it);
        return;
    }
    if (std::size_t(f1) >= ending_flat_.size())
        ending_flat_.resize(std::max(std::size_t(f1) + 1, 2 * ending_flat_.size()));
    ending_flat_[std::size_t(f1)] += std::size_t(delta);
}

// Expired entries leave a cell when something is next put into it (and one may have expired).
void BroadPhase::put(Cell& c, const Entry& e) const {
    const std::int64_t expired = expired_;
    if (c.ends <= expired) {
        auto& v = c.entries;
        v.erase(std::remove_if(v.begin(), v.end(), [expired](const Entry& x) { return x.box.f1 <= expired; }), v.end());
        c.ends = std::numeric_limits<std::int64_t>::max();
        for (const Entry& x : v) c.ends = std::min(c.ends, x.box.f1);
    }
    c.entries.push_back(e);
    c.ends = std::min(c.ends, e.box.f1);
}

void BroadPhase::insert(int id, int owner, const SpaceTimeBox& box) {
    MOBB_ASSERT(id >= 0);
    MOBB_ASSERT(box.x0 <= box.x1 && box.y0 <= box.y1 && box.f0 <= box.f1);
    if (!enroll(id, owner, box)) return;
    const Entry e = entry(box, id, owner);
    cells(box, [&](std::int64_t ix, std::int64_t iy) { put(cell(ix, iy), e); });
}

void BroadPhase::update(const std::vector<int>& removed, const std::vector<Insertion>& inserted,
                        util::WorkerPool& pool) {
    if (removed.empty() && inserted.empty()) return;  // no need to wake the pool
    std::size_t top = 0;
    for (const Insertion& in : inserted) {
        if (in.id < 0) throw std::invalid_argument("broad phase: negative id");
        top = std::max(top, std::size_t(in.id) + 1);
    }
    // An id both removed and inserted is replaced: its insertion alone stages where it was.
    MOBB_ASSERT(unplacing_.size == 0 && placing_.size == 0);  // nothing staged by the caller
    if (marks_.size() < top) marks_.resize(top);
    if (++mark_ == 0) {  // wrapped: no old mark may match
        std::fill(marks_.begin(), marks_.end(), 0);
        mark_ = 1;
    }
    for (const Insertion& in : inserted) marks_[std::size_t(in.id)] = mark_;
    const auto reinserted = [&](int id) {
        return id >= 0 && std::size_t(id) < top && marks_[std::size_t(id)] == mark_;
    };
    const std::size_t nr = removed.size();
    stage(nr, inserted.size());
    const auto stage_one = [&](std::size_t k, int) {
        if (k >= nr) return stage_inserted(k - nr, inserted[k - nr]);
        if (reinserted(removed[k])) return void(unplacing_[k] = {});
        stage_removed(k, removed[k]);
    };
    // A few items are not worth waking the pool for.
    if (nr + inserted.size() < kFewItems) {
        for (std::size_t k = 0; k < nr + inserted.size(); ++k) stage_one(k, 0);
    } else {
        pool.for_each(nr + inserted.size(), stage_one, 64);
    }
    apply_staged(pool);
}

void BroadPhase::stage(std::size_t removed, std::size_t inserted) {
    unplacing_.resize(removed);
    replacing_.resize(inserted);
    placing_.resize(inserted);
}

// Bands of columns: a cell belongs to one band (one band for one thread: each band visits every item).
// A cell's order does not matter (queries sort or order their answers). One more task beside them, first
// so that it does not end the step alone, enters the items in the table, counts them and enters the
// hashed cells, which no band touches; a few items do it all in turn.
void BroadPhase::apply_staged(util::WorkerPool& pool) {
    const bool few = unplacing_.size + placing_.size < kFewItems;
    if (unplacing_.size + placing_.size == 0) return;
    const std::int64_t bands = pool.size() > 1 && !few ? std::min<std::int64_t>(nx_, 4 * std::int64_t(pool.size())) : 1;
    if (few) {
        enter_staged();
        fill_band(0, 1);
    } else {
        pool.for_each(std::size_t(bands + 1), [&](std::size_t task, int) {
            if (task == 0) return enter_staged();
            fill_band(std::int64_t(task) - 1, bands);
        });
    }
    stage(0, 0);
}

// The staged items in the table (the removed first: an inserted id still held leaves first too) and in
// the counts, and their hashed cells: on one thread (hashing is not thread-safe).
void BroadPhase::enter_staged() {
    std::size_t top = 0;
    for (const Placing& p : placing_) top = std::max(top, std::size_t(p.e.id) + 1);
    // Doubling: ids come a few more at a time, and resize() to each would take its slow path each time.
    if (top > items_.size()) items_.resize(std::max(top, 2 * items_.size()));
    for (const Placing& p : unplacing_)
        if (p.ix0 <= p.ix1) items_[std::size_t(p.e.id)].live = false;
    for (const Placing& p : replacing_)
        if (p.ix0 <= p.ix1) items_[std::size_t(p.e.id)].live = false;
    for (const Placing& p : placing_)
        if (p.ix0 <= p.ix1) items_[std::size_t(p.e.id)] = {p.e.box, p.e.owner, true};
    count(unplacing_, -1);
    count(replacing_, -1);
    count(placing_, +1);
    update_hashed();
}

// The flat cells of band `band` of `bands` (of columns): the staged items leave them, then enter them.
void BroadPhase::fill_band(std::int64_t band, std::int64_t bands) {
    const std::int64_t lo = nx_ * band / bands, hi = nx_ * (band + 1) / bands;
    const auto each_cell = [&](const Placing& p, auto&& f) {
        const std::int64_t ix0 = std::max(lo, p.ix0), ix1 = std::min(hi - 1, p.ix1);
        const std::int64_t iy0 = std::max<std::int64_t>(0, p.iy0), iy1 = std::min(ny_ - 1, p.iy1);
        for (std::int64_t ix = ix0; ix <= ix1; ++ix)
            for (std::int64_t iy = iy0; iy <= iy1; ++iy) f(flat_[std::size_t(ix * ny_ + iy)]);
    };
    for (const Placing& p : unplacing_) each_cell(p, [&](Cell& c) { erase(c, p.e.id); });
    for (const Placing& p : replacing_) each_cell(p, [&](Cell& c) { erase(c, p.e.id); });
    for (const Placing& p : placing_) each_cell(p, [&](Cell& c) { put(c, p.e); });
}

// The held count and the counts by end frame, for items that left (-1) or entered (+1) the table.
void BroadPhase::count(const Placings& items, int delta) {
    for (const Placing& p : items) {
        if (p.ix0 > p.ix1) continue;  // none
        live_ += std::size_t(delta);
        count_end(p.e.box.f1, delta);
    }
}

// The cells of update() beyond the flat ones, on one thread (hashing is not thread-safe).
void BroadPhase::update_hashed() {
    const auto beyond = [&](const Placing& p, auto&& f) {
        if (p.ix0 > p.ix1 || (p.ix0 >= 0 && p.iy0 >= 0 && p.ix1 < nx_ && p.iy1 < ny_)) return;  // none, or flat
        for (std::int64_t ix = p.ix0; ix <= p.ix1; ++ix)
            for (std::int64_t iy = p.iy0; iy <= p.iy1; ++iy)
                if (!flat(ix, iy)) f(hashed_[key(ix, iy)]);
    };
    for (const Placing& p : unplacing_) beyond(p, [&](Cell& c) { erase(c, p.e.id); });
    for (const Placing& p : replacing_) beyond(p, [&](Cell& c) { erase(c, p.e.id); });
    for (const Placing& p : placing_) beyond(p, [&](Cell& c) { put(c, p.e); });
}

// Counts only: an expired item's own flag stays set (held() reads the frame too), so expiry touches no
// item, and the counts per end frame are few (the frames of the clips in play).
void BroadPhase::expire(std::int64_t frame) {
    expired_ = std::max(expired_, frame);
    for (auto it = ending_.begin(); it != ending_.end() && it->first <= expired_; it = ending_.erase(it))
        live_ -= it->second;
    const std::int64_t last = std::min<std::int64_t>(expired_, std::int64_t(ending_flat_.size()) - 1);
    for (; counted_from_ <= last; ++counted_from_) {
        live_ -= ending_flat_[std::size_t(counted_from_)];
        ending_flat_[std::size_t(counted_from_)] = 0;
    }
    if (expired_ == std::numeric_limits<std::int64_t>::max()) live_ -= std::exchange(ending_never_, 0);
}

// A cell's order does not matter (query() sorts its answer): the last entry fills the gap.
void BroadPhase::erase(Cell& c, int id) {
    auto& v = c.entries;
    const auto it = std::find_if(v.begin(), v.end(), [id](const Entry& e) { return e.id == id; });
    if (it == v.end()) return;  // dropped with the expired ones
    *it = v.back();
    v.pop_back();
}

void BroadPhase::remove(int id) {
    if (!holds(id)) return;
    Item& item = items_[std::size_t(id)];
    cells(item.box, [&](std::int64_t ix, std::int64_t iy) { erase(cell(ix, iy), id); });
    item.live = false;
    --live_;
    count_end(item.box.f1, -1);
}

void BroadPhase::query(const SpaceTimeBox& box, int owner, std::vector<int>& out, bool ascending) const {
    out.clear();
    const std::int64_t qx = index_x(box.x0), qy = index_y(box.y0), qx1 = index_x(box.x1), qy1 = index_y(box.y1);
    const std::int64_t expired = expired_;
    // SpaceTimeBox::overlaps on the ground: x0 <= box.x1, box.x0 <= x1 and the same for y, two at a time.
#if defined(__SSE2__)
    static_assert(offsetof(SpaceTimeBox, y0) == offsetof(SpaceTimeBox, x0) + sizeof(double) &&
                  offsetof(SpaceTimeBox, y1) == offsetof(SpaceTimeBox, x1) + sizeof(double));
    const __m128d lo = _mm_loadu_pd(&box.x0), hi = _mm_loadu_pd(&box.x1);  // (x0, y0), (x1, y1)
    const auto ground_overlaps = [&](const SpaceTimeBox& b) {
        return _mm_movemask_pd(
                   _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(&b.x0), hi), _mm_cmple_pd(lo, _mm_loadu_pd(&b.x1)))) == 3;
    };
#else
    const auto ground_overlaps = [&](const SpaceTimeBox& b) {
        return b.x0 <= box.x1 && box.x0 <= b.x1 && b.y0 <= box.y1 && box.y0 <= b.y1;
    };
#endif
    const auto scan = [&](const Cell& c, std::int64_t ix, std::int64_t iy) {
        // An item spans several cells: report it only from the cell holding the lower corner of the
        // two boxes' intersection, which both cover (the query's first column, or the item's when it
        // starts further on; rows alike). No visited marks, so the query is const. Tested first: it
        // is the cheapest test, and rules out an item in every cell but one.
        const bool first_x = ix == qx, first_y = iy == qy;
        const auto cx = std::int32_t(ix), cy = std::int32_t(iy);
        for (const Entry& e : c.entries) {
            if (!ground_overlaps(e.box)) continue;  // most entries fail here: tested first, without branches
            if ((!first_x && e.ix != cx) || (!first_y && e.iy != cy)) continue;
            if (e.owner == owner || e.box.f1 <= expired || !(e.box.f0 < box.f1 && box.f0 < e.box.f1)) continue;
            out.push_back(e.id);
        }
    };
    if (flat(qx, qy) && flat(qx1, qy1)) {  // the common case: no hashing, so no duplicates
        for (std::int64_t ix = qx; ix <= qx1; ++ix) {
            const Cell* column = &flat_[std::size_t(ix * ny_)];
            for (std::int64_t iy = qy; iy <= qy1; ++iy) scan(column[iy], ix, iy);
        }
        if (ascending && !std::is_sorted(out.begin(), out.end())) std::sort(out.begin(), out.end());
        return;
    }
    for (std::int64_t ix = qx; ix <= qx1; ++ix)
        for (std::int64_t iy = qy; iy <= qy1; ++iy)
            if (const Cell* c = find(ix, iy)) scan(*c, ix, iy);
    std::sort(out.begin(), out.end());
    // Two far cells may share a hash key, or the low bits of their indices; then an item could be met
    // twice.
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace mobb::crowd
