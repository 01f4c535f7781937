#include "mobb/util/median.h"

#include <algorithm>

namespace mobb::util {

double median(std::vector<double> v) {
    const std::size_t n = v.size();
    if (n == 0) return 0.0;
    const auto mid = v.begin() + std::ptrdiff_t(n / 2);
    std::nth_element(v.begin(), mid, v.end());
    if (n % 2) return *mid;
    return 0.5 * (*std::max_element(v.begin(), mid) + *mid);
}

}  // namespace mobb::util
