#include "mobb/crowd/metrics/flow.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "mobb/util/median.h"

namespace mobb::crowd {

FlowLine parse_flow_line(const std::string& text) {
    const auto bad = [&] { return std::invalid_argument("bad line '" + text + "': expected x=METRES or y=METRES"); };
    std::size_t i = text.find_first_not_of(' ');
    if (i == std::string::npos || (text[i] != 'x' && text[i] != 'y')) throw bad();
    const int axis = text[i] == 'x' ? 0 : 1;
    i = text.find_first_not_of(' ', i + 1);
    if (i == std::string::npos || text[i] != '=') throw bad();
    const std::string number = text.substr(i + 1);
    std::size_t used = 0;
    double at = 0;
    try {
        at = std::stod(number, &used);
    } catch (const std::exception&) {
        throw bad();
    }
    if (number.find_first_not_of(' ', used) != std::string::npos || !std::isfinite(at)) throw bad();
    return {axis, at};
}

FlowCounter::FlowCounter(FlowLine line, std::size_t agents)
    : line_(line), last_(agents, std::numeric_limits<double>::quiet_NaN()), seen_(agents, -1) {}

void FlowCounter::add(const SampleWindow& w) {
    const std::size_t width = w.width();
    for (std::int64_t f = w.first; f < w.last; ++f) {
        for (std::size_t k = 0; k < width; ++k) {
            const std::size_t a = w.agent_first + k;
            if (a >= last_.size() || f <= seen_[a] || (seen_[a] >= 0 && std::isnan(last_[a]))) continue;  // done
            const double v = w.samples[std::size_t(f - w.first) * width + k][1 + std::size_t(line_.axis)];
            const double before = last_[a];
            const std::int64_t prev = seen_[a];
            last_[a] = v, seen_[a] = f;  // NaN: it left the run, and is done
            if (std::isnan(v) || std::isnan(before) || (before < line_.at) == (v < line_.at)) continue;
            const double share = (line_.at - before) / (v - before);
            crossed_.push_back({a, (double(prev) + share * double(f - prev)) * w.dt, v > before ? 1 : -1});
            last_[a] = std::numeric_limits<double>::quiet_NaN();  // crossed: done
        }
    }
}

std::vector<Crossing> FlowCounter::crossings() const {
    std::vector<Crossing> c = crossed_;
    std::sort(c.begin(), c.end(), [](const Crossing& a, const Crossing& b) {
        return a.time < b.time || (a.time == b.time && a.agent < b.agent);
    });
    return c;
}

Flow flow_of(const std::vector<Crossing>& crossings) {
    Flow f;
    f.crossings = crossings.size();
    if (crossings.empty()) return f;
    for (const Crossing& c : crossings) (c.way > 0 ? f.forward : f.backward) += 1;
    f.first = crossings.front().time, f.last = crossings.back().time;
    const std::size_t n = crossings.size();
    if (n >= 2) {
        std::vector<double> gaps;
        gaps.reserve(n - 1);
        for (std::size_t i = 1; i < n; ++i) gaps.push_back(crossings[i].time - crossings[i - 1].time);
        f.median_headway = util::median(std::move(gaps));
    }
    if (n < 3) return f;
    const auto at = [&](double q) { return std::size_t(std::lround(q * double(n - 1))); };
    const std::size_t i10 = at(0.1), i90 = at(0.9);
    f.rate_from = crossings[i10].time, f.rate_to = crossings[i90].time;
    if (f.rate_to > f.rate_from) f.rate = double(i90 - i10) / (f.rate_to - f.rate_from);
    return f;
}

}  // namespace mobb::crowd
