// Broad phase of the crowd (paper section 5): a uniform grid over the ground holding the space-time
// bounding boxes of the clips agents have committed to, so a candidate clip is queried only against
// clips that can be near.
#pragma once
#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mobb/core/assert.h"

namespace mobb::util {
class WorkerPool;
}

namespace mobb::crowd {

/// Axis-aligned box in space-time: ground rectangle (metres) and global frames [f0, f1).
struct SpaceTimeBox {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    std::int64_t f0 = 0, f1 = 0;

    /// Grows to hold `o` too (the union's bounding box).
    void enclose(const SpaceTimeBox& o) {
        x0 = std::min(x0, o.x0), y0 = std::min(y0, o.y0), f0 = std::min(f0, o.f0);
        x1 = std::max(x1, o.x1), y1 = std::max(y1, o.y1), f1 = std::max(f1, o.f1);
    }
    /// Closed on the ground (touching rectangles overlap), half-open in time.
    bool overlaps(const SpaceTimeBox& o) const {
        return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1 && f0 < o.f1 && o.f0 < f1;
    }
};

/// Uniform grid of square cells, unbounded: the cells over an optional rectangle (the world) sit in a
/// flat array, the others are hashed (agents may leave the world). Items are caller-chosen ids with an
/// owner (the agent): queries skip the asker's own items.
///
/// Threads: query() is const and keeps no scratch state, so any number of threads may query at once
/// as long as nobody inserts or removes meanwhile (the crowd evaluates a frame's choice points in
/// parallel against a frozen grid, then commits sequentially).
class BroadPhase {
public:
    static constexpr std::int64_t kMaxFlatCells = std::int64_t(1) << 20;
    /// update() of fewer items (removed and inserted together) runs on the calling thread: waking the
    /// pool would cost more than the items do. Its outcome is the same either way. (256 until issue 46's
    /// sixth stop: the updates before a re-evaluation, 64 to 256 items, were then 1.2 % of the frame step
    /// on one thread alone; with 64, 2 threads run as fast at 10,000 and 100,000 agents - bench/results/log.md.)
    static constexpr std::size_t kFewItems = 64;

    /// `cell`: side of a grid cell, metres. Throws std::invalid_argument unless cell > 0.
    explicit BroadPhase(double cell = 4.0);
    /// The same with flat storage for the cells over [0, width] x [0, height] (metres), where most items
    /// are: no hashing there (unless that takes more than kMaxFlatCells cells). Throws
    /// std::invalid_argument unless cell > 0 and the sizes are >= 0.
    BroadPhase(double cell, double width, double height);
    /// The same over [x0, x1] x [y0, y1]. Throws std::invalid_argument unless cell > 0, x0 <= x1, y0 <= y1.
    BroadPhase(double cell, double x0, double y0, double x1, double y1);

    /// Adds (or replaces) item `id` >= 0; throws std::invalid_argument for a negative id. Ids index a
    /// table, so keep them dense: the id of an item removed or expired may be used again.
    void insert(int id, int owner, const SpaceTimeBox& box);
    struct Insertion {
        int id = 0, owner = -1;
        SpaceTimeBox box;
    };
    /// The same as insert() of each, in order, for distinct ids that are not held; the flat cells are filled
    /// by `pool`'s workers, each owning a band of grid columns (the crowd commits a frame's clips at
    /// once). Throws std::invalid_argument for a negative id.
    void insert_all(const std::vector<Insertion>& items, util::WorkerPool& pool) { update({}, items, pool); }
    /// The same as remove() of each of `removed`, then insert() of each of `inserted` (an id held is
    /// replaced), for ids distinct within each list, in two parallel steps: the items staged (below), then
    /// the flat cells filled by bands of columns. Not between stage() and apply_staged().
    void update(const std::vector<int>& removed, const std::vector<Insertion>& inserted, util::WorkerPool& pool);
    /// update() in steps, for a caller that writes its lists in parallel (the crowd's commits): stage()
    /// grows the staged lists to `removed` and `inserted` items (what is staged stays); stage_removed()
    /// and stage_inserted() stage the k-th item of each - from any thread, each index once, with no id in
    /// both lists - and read the table only; apply_staged() then enters them all as update() would, in one
    /// parallel step rather than three, and empties the lists. Nothing changes before apply_staged():
    /// holds() and queries answer as before the items were staged.
    void stage(std::size_t removed, std::size_t inserted);
    void stage_removed(std::size_t k, int id) { unplacing_[k] = held_placing(id); }
    void stage_inserted(std::size_t k, const Insertion& in) {
        MOBB_ASSERT(in.id >= 0);
        replacing_[k] = held_placing(in.id);
        placing_[k] = in.box.f1 <= expired_ ? Placing{} : placing(entry(in.box, in.id, in.owner));
    }
    void apply_staged(util::WorkerPool& pool);
    /// Removes item `id`; unknown or removed ids are ignored.
    void remove(int id);
    /// Drops every item whose box ends at or before `frame` (f1 <= frame): they are no longer reported
    /// nor counted, and items inserted later ending by then are dropped too. Cells are cleaned lazily,
    /// when an item is next inserted into them, which is much cheaper than remove() per item (the
    /// crowd expires every committed clip once). `frame` never decreases: smaller values are ignored.
    void expire(std::int64_t frame);
    /// Ids of items of other owners whose boxes overlap `box` (SpaceTimeBox::overlaps), each once:
    /// ascending, or in no set order when `ascending` is false (for a caller that orders them its own way).
    void query(const SpaceTimeBox& box, int owner, std::vector<int>& out, bool ascending = true) const;
    /// Items held.
    std::size_t size() const { return live_; }
    /// Whether item `id` is held: inserted, and neither removed nor expired since.
    bool holds(int id) const { return id >= 0 && std::size_t(id) < items_.size() && held(items_[std::size_t(id)]); }

private:
    struct Item {
        SpaceTimeBox box;
        int owner = -1;
        bool live = false;  // inserted and not removed since (held() also asks it has not expired)
    };
    bool held(const Item& item) const { return item.live && item.box.f1 > expired_; }
    struct Entry {  // an item as a cell holds it: the box inline, so a query reads one array per cell
        SpaceTimeBox box;
        int id = 0, owner = -1;
        // The cell of the box's lower corner (index_x(box.x0), index_y(box.y0)), its low 32 bits: 64 bytes
        // an entry. (Far cells alike in them share a hash key too: query() drops the duplicates.)
        std::int32_t ix = 0, iy = 0;
    };
    struct Cell {
        std::vector<Entry> entries;
        std::int64_t ends = std::numeric_limits<std::int64_t>::max();  // no entry ends before (a lower bound)
    };
    struct Placing {  // an item of update(): its entry and the cells it covers (none: ix0 > ix1)
        Entry e;
        std::int64_t ix0 = 0, iy0 = 0, ix1 = -1, iy1 = -1;
    };
    // Scratch of update() that grows and never shrinks: its first `size` items are the update's. (A vector
    // resized to each update's count zeroes what it regrows, on the calling thread: a serial cost.)
    struct Placings {
        std::vector<Placing> buffer;
        std::size_t size = 0;
        void resize(std::size_t n) {
            if (buffer.size() < n) buffer.resize(n);
            size = n;
        }
        Placing& operator[](std::size_t k) { return buffer[k]; }
        const Placing* begin() const { return buffer.data(); }
        const Placing* end() const { return buffer.data() + size; }
    };
    Entry entry(const SpaceTimeBox& box, int id, int owner) const {
        return {box, id, owner, std::int32_t(index_x(box.x0)), std::int32_t(index_y(box.y0))};
    }
    // floor() by hand: the library call costs more than the rest of a cell lookup. Multiplying by the
    // inverse may put a box one cell over, but consistently (it is monotonic), which is all the grid needs.
    static std::int64_t floor_index(double v) {
        const auto i = std::int64_t(v);
        return i - std::int64_t(double(i) > v);
    }
    std::int64_t index_x(double x) const { return floor_index((x - x0_) * inv_cell_); }
    std::int64_t index_y(double y) const { return floor_index((y - y0_) * inv_cell_); }
    template <class F>
    void cells(const SpaceTimeBox& box, F&& f) const;
    Cell& cell(std::int64_t ix, std::int64_t iy);
    bool flat(std::int64_t ix, std::int64_t iy) const { return 0 <= ix && ix < nx_ && 0 <= iy && iy < ny_; }
    bool enroll(int id, int owner, const SpaceTimeBox& box);
    // Item `id`'s entry and cells while it is held; none (ix0 > ix1) when it is not.
    Placing held_placing(int id) const {
        if (!holds(id)) return {};
        const Item& item = items_[std::size_t(id)];
        return placing(entry(item.box, id, item.owner));
    }
    void enter_staged();
    void fill_band(std::int64_t band, std::int64_t bands);
    void count(const Placings& items, int delta);
    void update_hashed();
    Placing placing(const Entry& e) const {
        return {e, index_x(e.box.x0), index_y(e.box.y0), index_x(e.box.x1), index_y(e.box.y1)};
    }
    static void erase(Cell& c, int id);
    void put(Cell& c, const Entry& e) const;
    const Cell* find(std::int64_t ix, std::int64_t iy) const;
    static std::uint64_t key(std::int64_t ix, std::int64_t iy) {
        return (std::uint64_t(ix) << 32) ^ (std::uint64_t(iy) & 0xffffffffull);
    }

    double inv_cell_;
    double x0_ = 0, y0_ = 0;  // origin of the cells
    // Emptied cells keep their (empty) arrays: agents walk back and forth over the same ground, and
    // reusing the arrays saves an allocation per cell per clip.
    std::int64_t nx_ = 0, ny_ = 0;  // flat cells: ix in [0, nx), iy in [0, ny)
    std::vector<Cell> flat_;
    std::unordered_map<std::uint64_t, Cell> hashed_;
    std::vector<Item> items_;
    Placings unplacing_;                // staged: the items removed, where they were
    Placings replacing_;                // staged: where the items inserted were, when still held
    Placings placing_;                  // staged: the items inserted
    std::vector<std::uint32_t> marks_;  // update()'s: mark_ at the ids it inserts
    std::uint32_t mark_ = 0;
    std::size_t live_ = 0;
    std::int64_t expired_ = std::numeric_limits<std::int64_t>::min();  // items ending by then are gone
    // Items held, by the frame they end at: counted in an array for frames [0, kFlatEnds) (a clip's end;
    // a map costs more than a query), apart for the largest frame (held ground: for good), in a map
    // for the others.
    static constexpr std::int64_t kFlatEnds = std::int64_t(1) << 20;
    std::vector<std::size_t> ending_flat_;
    std::int64_t counted_from_ = 0;  // the frames of ending_flat_ below have been expired
    std::size_t ending_never_ = 0;
    std::map<std::int64_t, std::size_t> ending_;
    void count_end(std::int64_t f1, int delta) {
        if (0 <= f1 && std::size_t(f1) < ending_flat_.size())
            ending_flat_[std::size_t(f1)] += std::size_t(delta);
        else if (f1 == std::numeric_limits<std::int64_t>::max())
            ending_never_ += std::size_t(delta);
        else
            count_end_rarely(f1, delta);
    }
    void count_end_rarely(std::int64_t f1, int delta);
};

}  // namespace mobb::crowd
