// Every method timed on the same queries in one run, interleaved pass by pass, so a drift of a shared
// machine hits every row alike; answers compared with brute force.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "method.h"
#include "query_set.h"

namespace mobb::bench {

/// One row of a table: a method's mean time per query (microseconds, median over the timed passes),
/// mean work per query (tests counted in a separate, untimed pass), share of positive answers, and
/// answers that differ from the reference (brute force) on the queries the method answered.
struct MethodRow {
    std::optional<Method> method;  ///< empty for a row that is not a query method (frame stepping)
    std::string label;             ///< label(method), or the row's own name
    double us_per_query = 0;
    double x_sweep = 0;  ///< us_per_query / the circle sweep's (0 when there is none)
    double tests2d = 0, tests3d = 0, samples = 0;
    double positive = 0;
    std::uint64_t queries = 0;        ///< answered in the untimed pass (agreement, positives, tests)
    std::uint64_t timed_queries = 0;  ///< per timed pass (a prefix of the queries for slow methods)
    std::uint64_t disagreements = 0;
    std::uint64_t extra = 0,
                  missed = 0;  ///< of the disagreements: positive for this method only / for brute force only
    bool measured = true;      ///< false: the method could not run (see note)
    std::string note;
};

/// Times every method on the same queries: `passes` timed passes, methods interleaved within each
/// pass. Slow methods (QueryMethod::slow()) are timed on the first `slow_queries` queries only; FCL
/// also answers only those in the untimed pass. The brute-force row (if any; it answers every query) is
/// the reference for disagreements; x_sweep is filled from the circle sweep's row. Unavailable methods
/// get an unmeasured row. `progress` (may be empty) gets the fraction done.
std::vector<MethodRow> time_methods(const QuerySet& set, const std::vector<std::unique_ptr<QueryMethod>>& methods,
                                    int passes, const std::function<void(double)>& progress = {},
                                    std::size_t slow_queries = std::size_t(-1));

/// The measured row of `method`, or null.
const MethodRow* find_row(const std::vector<MethodRow>& rows, Method method);

/// Maps [0, 1] of a stage onto [lo, hi] of a whole run's progress (empty stays empty).
std::function<void(double)> progress_stage(const std::function<void(double)>& progress, double lo, double hi);

}  // namespace mobb::bench
