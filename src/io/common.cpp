#include "common.h"

#include <cmath>

namespace mobb::io::detail {

double snap_dt(double dt) {
    if (!(dt > 0) || !std::isfinite(dt)) return dt;
    const double rate = std::round(1.0 / dt);
    if (rate >= 1 && std::abs(dt * rate - 1.0) <= 1e-4) return 1.0 / rate;
    return dt;
}

std::string quote(std::string_view text, std::size_t max) {
    std::string out;
    for (std::size_t i = 0; i < text.size() && i < max; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        out += (c < 0x20 || c == 0x7f) ? '?' : char(c);
    }
    if (text.size() > max) out += "...";
    return out;
}

}  // namespace mobb::io::detail
