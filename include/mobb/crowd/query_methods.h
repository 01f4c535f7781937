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
    /// Slow methods (brute force, FCL) are timed on a prefix of the queries only (see time_methods).
    virtual bool slow() const { return false; }
    /// Empty when the method can run; otherwise why not (e.g. "built without FCL"): its row is kept,
    /// untimed, with this as its note.
    virtual std::string unavailable() const { return {}; }
    /// Caveat printed with the row (e.g. FCL's conservative model); empty when none.
    virtual std::string note() const { return {}; }
};

/// A core tree of one type (n_min samples per leaf) per clip, queried with collide().
std::unique_ptr<QueryMethod> tree_method(TreeType type, int n_min = 10);
/// The brute-force reference, collide_brute() on the paths.
std::unique_ptr<QueryMethod> brute_method();

/// The library's default query ("mobb"): a ClipIndex per clip, collide_fast() (core/fast_query.h).
/// Counts no tests (stats untouched).
std::unique_ptr<QueryMethod> mobb_method();
/// The best scan ("best scan"): a ClipIndex per clip, collide_scan() (core/scan.h).
std::unique_ptr<QueryMethod> scan_method();
/// The FCL peer ("FCL", bench/fcl_peer.h): one fcl::BVHModel<OBBRSSd> of 8-sided prisms circumscribing
/// the disks per clip, fcl::collide with a boolean request. Conservative: may report contacts the exact
/// model does not. When built without FCL (MOBB_WITH_FCL off or libfcl-dev missing) unavailable() says so.
std::unique_ptr<QueryMethod> fcl_method();
/// True when FCL was found at configure time.
bool fcl_built();

/// The rows of the paper's tables, in its order: MOBB 1 level, UMOBB 1 level, MOBB, UMOBB, Hybrid 1,
/// Hybrid 2, then brute force.
std::vector<std::unique_ptr<QueryMethod>> paper_methods(int n_min = 10);
/// The rows of every performance table (issue 5), in order: paper_methods(n_min), then best scan, FCL, mobb.
std::vector<std::unique_ptr<QueryMethod>> bench_methods(int n_min = 10);
/// One method by its row name (any of bench_methods()); throws std::invalid_argument for another name.
std::unique_ptr<QueryMethod> method_by_name(const std::string& name, int n_min = 10);

/// Whether the MOBB root boxes of two placed paths overlap in space-time (the first test of an MOBB
/// query; "root overlap" in the benchmarks).
bool roots_overlap(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb);

}  // namespace mobb::crowd
