#include "mobb/crowd/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mobb::crowd {

BroadPhase::BroadPhase(double cell) : cell_(cell) {
    if (!(cell > 0)) throw std::invalid_argument("broad phase: cell size must be positive");
}

template <class F>
void BroadPhase::cells(const SpaceTimeBox& box, F&& f) const {
    const auto ix0 = std::int64_t(std::floor(box.x0 / cell_)), ix1 = std::int64_t(std::floor(box.x1 / cell_));
    const auto iy0 = std::int64_t(std::floor(box.y0 / cell_)), iy1 = std::int64_t(std::floor(box.y1 / cell_));
    for (std::int64_t ix = ix0; ix <= ix1; ++ix)
        for (std::int64_t iy = iy0; iy <= iy1; ++iy) f(key(ix, iy));
}

void BroadPhase::insert(int id, int owner, const SpaceTimeBox& box) {
    if (id < 0) throw std::invalid_argument("broad phase: negative id");
    if (std::size_t(id) >= items_.size()) {
        items_.resize(std::size_t(id) + 1);
        stamp_.resize(std::size_t(id) + 1, 0);
    }
    Item& item = items_[std::size_t(id)];
    if (item.live) remove(id);
    item = {box, owner, true};
    ++live_;
    cells(box, [&](std::uint64_t k) { grid_[k].push_back(id); });
}

void BroadPhase::remove(int id) {
    if (id < 0 || std::size_t(id) >= items_.size() || !items_[std::size_t(id)].live) return;
    Item& item = items_[std::size_t(id)];
    cells(item.box, [&](std::uint64_t k) {
        auto it = grid_.find(k);
        if (it == grid_.end()) return;
        auto& v = it->second;
        v.erase(std::remove(v.begin(), v.end(), id), v.end());
        if (v.empty()) grid_.erase(it);
    });
    item.live = false;
    --live_;
}

void BroadPhase::query(const SpaceTimeBox& box, int owner, std::vector<int>& out) {
    out.clear();
    ++query_;
    cells(box, [&](std::uint64_t k) {
        const auto it = grid_.find(k);
        if (it == grid_.end()) return;
        for (int id : it->second) {
            if (stamp_[std::size_t(id)] == query_) continue;
            stamp_[std::size_t(id)] = query_;
            const Item& item = items_[std::size_t(id)];
            if (item.owner != owner && item.box.overlaps(box)) out.push_back(id);
        }
    });
    std::sort(out.begin(), out.end());
}

}  // namespace mobb::crowd
