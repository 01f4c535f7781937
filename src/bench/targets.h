// A target of the performance issues as measured in one run: a speed or cost ratio, or a count.
#pragma once
#include <string>
#include <vector>

#include "method.h"
#include "timing.h"

namespace mobb::bench {

/// `measured` is a speed ratio (higher is better, met when >= goal) unless `at_most`, then a cost
/// ratio or a count (met when <= goal).
struct Target {
    std::string what;  ///< e.g. "circle sweep >= 25x faster than MOBB 1 level"
    double goal = 1, measured = 0;
    bool at_most = false;
    bool known = true;   ///< false: not measurable in this run (see detail)
    bool ratio = true;   ///< false: a count (e.g. contacts), printed without "x"
    std::string detail;  ///< how measured, or why not
    bool met() const { return known && (at_most ? measured <= goal : measured >= goal); }
};

/// A count or a share that must stay at most `goal` (printed as a number), or a cost ratio (`ratio`:
/// printed with "x").
Target at_most(const std::string& what, double goal, double measured, const std::string& detail, bool ratio = false);
/// A count or a share that must reach `goal`.
Target at_least(const std::string& what, double goal, double measured, const std::string& detail);

/// "circle sweep >= goal x faster than <peer>", measured on the rows' times per query; unknown when a
/// row is missing.
Target speed_target(const std::vector<MethodRow>& rows, Method peer, double goal);

/// "measured 12.3x, goal >= 25x: MISSED (2.03x short)", or "... met", or "not measured".
std::string target_text(const Target& t);

}  // namespace mobb::bench
