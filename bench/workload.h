// One long-clip workload for every method at once: two ~42 s real sequences, each prepared once per
// method (trees of every paper type, the fast query's ClipIndex, an FCL model), and a fixed list of
// random placements. Shared by the micro-benchmarks and the callgrind driver.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "fcl_peer.h"
#include "mobb/core/brute.h"
#include "mobb/core/clip_index.h"
#include "mobb/core/fast_query.h"
#include "mobb/core/query.h"
#include "mobb/core/scan.h"
#include "mobb/core/tree.h"
#include "sequences.h"

namespace mobb::bench {

/// Methods compared: the paper's tree types (TreeType order), then brute force, best scan, the fast
/// query and FCL.
enum class Method { Mobb, Umobb, Hybrid1, Hybrid2, Mobb1, Umobb1, Brute, Scan, Fast, Fcl };
constexpr int kMethods = 10;
const char* to_string(Method m);
Method parse_method(const std::string& name);  ///< throws std::invalid_argument

struct Workload {
    Path a, b;
    std::vector<Tree> trees_a, trees_b;  // [TreeType]
    ClipIndex index_a, index_b;
    std::vector<FclClip> fcl;            // a, b; empty unless built with fcl = true
    Placements places;

    static constexpr std::size_t kPlacements = 4096;
    static Workload make(double fps, bool fcl);
    std::size_t size() const { return places.a.size(); }

    /// Query i of the list with method m.
    bool query(Method m, std::size_t i) const {
        const Placement& pa = places.a[i];
        const Placement& pb = places.b[i];
        switch (m) {
            case Method::Brute: return collide_brute(a, pa, b, pb);
            case Method::Scan: return collide_scan(index_a, pa, index_b, pb);
            case Method::Fast: return collide_fast(index_a, pa, index_b, pb);
            case Method::Fcl: return fcl_collide(fcl[0], pa, fcl[1], pb);
            default: return collide(trees_a[std::size_t(m)], pa, trees_b[std::size_t(m)], pb);
        }
    }
};

}  // namespace mobb::bench
