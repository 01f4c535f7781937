// Issue 5's workloads for the fast query, each prepared once for the methods compared side by side:
// the crowd's own narrow-phase queries (Table 1 like), random tests on the longest CMU clips (Table 2
// like) and on long motion-graph sequences (Table 2 --synth like). Benchmarks only, never the core.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "mobb/core/clip_index.h"
#include "mobb/core/fast_query.h"
#include "mobb/core/query.h"
#include "mobb/core/scan.h"
#include "mobb/core/tree.h"

namespace mobb::bench {

/// fast = collide_fast, scan = collide_scan, mobb1 = collide() on the paper's 1-level tree, mobb =
/// collide() on the MOBB tree (n_min 10).
enum class CrowdMethod { Fast, Scan, Mobb1, Mobb };
constexpr int kCrowdMethods = 4;
const char* to_string(CrowdMethod m);
CrowdMethod parse_crowd_method(const std::string& name);  ///< throws std::invalid_argument

struct ClipQuery {
    int a = 0, b = 0;
    Placement pa, pb;
};

struct ClipWorkload {
    std::string name, description;
    std::vector<Path> paths;
    std::vector<ClipIndex> index;
    std::vector<Tree> mobb1, mobb;
    std::vector<ClipQuery> queries;

    std::size_t size() const { return queries.size(); }
    bool query(CrowdMethod m, std::size_t i) const {
        const ClipQuery& q = queries[i];
        const auto a = std::size_t(q.a), b = std::size_t(q.b);
        switch (m) {
            case CrowdMethod::Fast: return collide_fast(index[a], q.pa, index[b], q.pb);
            case CrowdMethod::Scan: return collide_scan(index[a], q.pa, index[b], q.pb);
            case CrowdMethod::Mobb1: return collide(mobb1[a], q.pa, mobb1[b], q.pb);
            default: return collide(mobb[a], q.pa, mobb[b], q.pb);
        }
    }

    /// "crowd": run_crowd (100 agents, 30 x 40 m, 60 s, random selection, seed 1) on
    /// assets/graphs/cmu_locomotion.json, every logged query. "longest": the 14 longest CMU clips at
    /// 30 Hz. "synth42", "synth120": 14 random walks of the motion graph of 42 s or 120 s. The last
    /// three get `tests` random tests as in run_table2 (random rotation, centre in a disk whose radius
    /// gives 81.3 % root overlaps, time offset uniform over the overlapping range). Throws
    /// std::runtime_error without the mocap data.
    static ClipWorkload make(const std::string& name, int tests = 20000);
};

}  // namespace mobb::bench
