// The crowd's narrow phase: does one placed graph clip collide with another? The library's fastest exact
// query by default (a ClipIndex per clip and collide_sweep), or the paper's trees with their counters
// (Table 1 times the crowd's queries with them). Built once per motion graph, then read by any thread.
#pragma once
#include <vector>

#include "mobb/core/clip_index.h"
#include "mobb/core/query.h"
#include "mobb/core/tree.h"
#include "mobb/crowd/graph/motion_graph.h"

namespace mobb::crowd {

class NarrowPhase {
public:
    /// collide_sweep on a ClipIndex per graph clip (core/sweep.h): counts nothing.
    static NarrowPhase sweep(const MotionGraph& graph);
    /// collide() on a tree of these options per graph clip (core/query.h): counts the paper's tests.
    static NarrowPhase trees(const MotionGraph& graph, const TreeOptions& options);

    /// Graph clip a placed at pa against graph clip b placed at pb; adds tests to `stats` when not null.
    bool operator()(int a, const Placement& pa, int b, const Placement& pb, QueryStats* stats = nullptr) const;
    /// The same with the placements' rotations given (ma == Rigid2::of(pa), mb == Rigid2::of(pb)).
    bool operator()(int a, const Placement& pa, const Rigid2& ma, int b, const Placement& pb, const Rigid2& mb,
                    QueryStats* stats = nullptr) const;

    /// "sweep", or the tree type's name.
    const char* name() const;
    /// The trees (empty for the sweep).
    const std::vector<Tree>& tree_list() const { return trees_; }

private:
    std::vector<ClipIndex> index_;
    std::vector<Tree> trees_;
};

/// One clip-against-clip narrow-phase query of a run: clip a at pa (the candidate's, or an escape clip of
/// the route tried) against clip b at pb (another agent's, committed or reserved).
struct LoggedQuery {
    int choice = 0, candidate = 0;  ///< indices into Record::choices and its candidates
    int clip_a = 0, clip_b = 0;
    Placement pa, pb;
    bool hit = false;
};

}  // namespace mobb::crowd
