// The ways of answering one space-time query that the benchmarks time side by side: the paper's trees,
// brute force, the best scan, the circle sweep and FCL. One list (Method, with its name table); each
// is built once per set of clips and then asked yes/no questions through QueryMethod.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/core/query.h"
#include "mobb/core/tree.h"

namespace mobb::bench {

/// The paper's tree types first, in TreeType order, then the peers.
enum class Method : std::uint8_t {
    Mobb,
    Umobb,
    Hybrid1,
    Hybrid2,
    Mobb1,
    Umobb1,  ///< collide() on a tree of that type (paper 3-5)
    Brute,   ///< collide_brute(): the reference
    Scan,    ///< collide_scan(): the best scan
    Sweep,   ///< collide_sweep(): the circle sweep, the library's default exact query
    Fcl,     ///< the FCL peer (fcl_peer.h)
};
inline constexpr int kMethodCount = 10;
/// The library's default exact query (what the crowd and Python's mobb.collide call): its row in the
/// bench JSON carries "default": true.
inline constexpr Method kDefaultMethod = Method::Sweep;

/// Short name (command lines, scripts: "mobb", ..., "brute", "scan", "sweep", "fcl") and row label
/// (tables: "MOBB", "MOBB 1 level", ..., "brute force", "best scan", "circle sweep", "FCL"). The tree
/// methods take both from the core's tree-type table.
const char* key(Method m);
const char* label(Method m);
/// The method of a key or a label; throws std::invalid_argument naming the keys.
Method parse_method(const std::string& name);
/// The tree type of a tree method.
std::optional<TreeType> tree_type(Method m);

/// The rows of the paper's tables, in its order: MOBB 1 level, UMOBB 1 level, MOBB, UMOBB, Hybrid 1,
/// Hybrid 2, then brute force.
std::vector<Method> paper_methods();
/// The rows of every performance table: paper_methods(), then best scan, FCL, circle sweep.
std::vector<Method> table_methods();

class QueryMethod {
public:
    virtual ~QueryMethod() = default;
    virtual Method method() const = 0;
    /// Builds what the method needs for these clips (not timed). Clip ids index this vector.
    virtual void prepare(const std::vector<Path>& clips) = 0;
    /// Does clip a placed at pa collide with clip b placed at pb? Same predicate as core collide().
    /// Adds its work to stats when not null (the trees and brute force count; the others do not).
    virtual bool query(int a, const Placement& pa, int b, const Placement& pb, QueryStats* stats) const = 0;
    /// Slow methods (brute force, FCL) are timed on a prefix of the queries only (see time_methods).
    virtual bool slow() const { return false; }
    /// Empty when the method can run; otherwise why not (e.g. "built without FCL"): its row is kept,
    /// untimed, with this as its note.
    virtual std::string unavailable() const { return {}; }
    /// Caveat printed with the row (e.g. FCL's conservative model); empty when none.
    virtual std::string note() const { return {}; }
};

/// The method, trees with n_min samples per leaf.
std::unique_ptr<QueryMethod> make_method(Method m, int n_min = 10);
std::vector<std::unique_ptr<QueryMethod>> make_methods(const std::vector<Method>& methods, int n_min = 10);

/// The FCL peer as a method (fcl_method.cpp): one fcl::BVHModel<OBBRSSd> of 8-sided prisms circumscribing
/// the disks per clip, fcl::collide with a boolean request. Conservative: may report contacts the exact
/// model does not. Built without FCL (MOBB_WITH_FCL off or libfcl-dev missing), unavailable() says so.
std::unique_ptr<QueryMethod> fcl_method();

/// Whether the MOBB root boxes of two placed trees overlap in space-time (the first box test of an
/// MOBB query): the benchmarks' "root overlap".
bool root_boxes_overlap(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb);

}  // namespace mobb::bench
