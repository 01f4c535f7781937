// A benchmark workload: clips and the queries every method answers, as one value and as a text file
// (for the callgrind driver, bench/query_driver.cpp).
#pragma once
#include <string>
#include <vector>

#include "mobb/core/path.h"

namespace mobb::bench {

/// One query to replay: clip a at pa against clip b at pb (ids index QuerySet::clips).
struct ClipQuery {
    int a = 0, b = 0;
    Placement pa, pb;
};

struct QuerySet {
    std::vector<Path> clips;
    std::vector<ClipQuery> queries;
};

/// Writes a query set as text:
///   mobb query set 1
///   clips C
///   clip DT N            then N lines "x y r"            (metres, seconds; C times)
///   queries Q            then Q lines "a b xa ya thetaa t0a xb yb thetab t0b"
/// with 17 significant digits, so a set reads back bit for bit. Throws std::runtime_error when the file
/// cannot be written.
void save_query_set(const QuerySet& set, const std::string& file);
/// Reads save_query_set()'s file. Throws std::runtime_error "FILE: ..." on any problem.
QuerySet load_query_set(const std::string& file);

}  // namespace mobb::bench
