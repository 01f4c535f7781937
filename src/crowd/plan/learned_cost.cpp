#include "plan/learned_cost.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mobb::crowd {

std::int64_t LearnedCost::key(double x, double y) {
    const auto ix = std::int64_t(std::floor(x / kCell)), iy = std::int64_t(std::floor(y / kCell));
    return ix * 0x100000000LL + (iy & 0xffffffffLL);
}

std::size_t LearnedCost::find(std::int64_t k) const {
    const std::size_t mask = slots_.size() - 1;
    // Cells along x differ in the high half of the key: mix it down (Fibonacci hashing).
    std::size_t i = std::size_t((std::uint64_t(k) * 0x9E3779B97F4A7C15ULL) >> 20) & mask;
    while (slots_[i].used && slots_[i].key != k) i = (i + 1) & mask;
    return i;
}

double LearnedCost::at(double x, double y) const {
    if (slots_.empty()) return 0.0;
    const Slot& s = slots_[find(key(x, y))];
    return s.used ? s.seconds : 0.0;
}

void LearnedCost::raise(double x, double y, double seconds) {
    if (2 * (used_ + 1) > slots_.size()) {  // grow: at most half full
        std::vector<Slot> old = std::exchange(slots_, std::vector<Slot>(std::max<std::size_t>(16, 2 * slots_.size())));
        for (const Slot& s : old)
            if (s.used) slots_[find(s.key)] = s;
    }
    const std::int64_t k = key(x, y);
    Slot& s = slots_[find(k)];
    if (!s.used) s = {k, 0.0, true}, ++used_;
    s.seconds = std::max(s.seconds, seconds);
}

void LearnedCost::clear() {
    slots_.clear();
    used_ = 0;
}

}  // namespace mobb::crowd
