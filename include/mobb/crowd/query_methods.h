// The ways of answering one space-time query that the benchmarks time side by side. Each is built once
// per set of clips and then asked yes/no questions; add a method (a scan, FCL, ...) by implementing
// QueryMethod and appending it to the list the benchmark receives.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/core/query.h"
#include "mobb/core/tree.h"

namespace mobb::crowd {

class QueryMethod {
public:
    virtual ~QueryMethod() = default;
    /// Row name in the tables, e.g. "MOBB 1 level".
    virtual std::string name() const = 0;
    /// Builds what the method needs for these clips (not timed). Clip ids index this vector.
    virtual void prepare(const std::vector<Path>& clips) = 0;
    /// Does clip a placed at pa collide with clip b placed at pb? Same predicate as core collide().
    /// Adds its work to stats when not null.
    virtual bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats* stats) const = 0;
};

/// A core tree of one type (n_min samples per leaf) per clip, queried with collide().
std::unique_ptr<QueryMethod> tree_method(TreeType type, int n_min = 10);
/// The brute-force reference, collide_brute() on the paths.
std::unique_ptr<QueryMethod> brute_method();

/// The rows of the paper's tables, in its order: MOBB 1 level, UMOBB 1 level, MOBB, UMOBB, Hybrid 1,
/// Hybrid 2, then brute force.
std::vector<std::unique_ptr<QueryMethod>> paper_methods(int n_min = 10);

/// Whether the MOBB root boxes of two placed paths overlap in space-time (the first test of an MOBB
/// query; "root overlap" in the benchmarks).
bool roots_overlap(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb);

}  // namespace mobb::crowd
