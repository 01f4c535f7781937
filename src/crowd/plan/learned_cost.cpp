#include "plan/learned_cost.h"

#include <algorithm>
#include <cmath>

namespace mobb::crowd {

std::int64_t LearnedCost::key(double x, double y) {
    const auto ix = std::int64_t(std::floor(x / kCell)), iy = std::int64_t(std::floor(y / kCell));
    return ix * 0x100000000LL + (iy & 0xffffffffLL);
}

double LearnedCost::at(double x, double y) const {
    const auto it = value_.find(key(x, y));
    return it == value_.end() ? 0.0 : it->second;
}

void LearnedCost::raise(double x, double y, double seconds) {
    double& v = value_[key(x, y)];
    v = std::max(v, seconds);
}

}  // namespace mobb::crowd
