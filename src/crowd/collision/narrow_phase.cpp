#include "mobb/crowd/collision/narrow_phase.h"

#include "mobb/core/sweep.h"

namespace mobb::crowd {

NarrowPhase NarrowPhase::sweep(const MotionGraph& graph) {
    NarrowPhase n;
    for (const GraphClip& c : graph.clips) n.index_.push_back(ClipIndex::build(c.path));
    return n;
}

NarrowPhase NarrowPhase::trees(const MotionGraph& graph, const TreeOptions& options) {
    NarrowPhase n;
    for (const GraphClip& c : graph.clips) n.trees_.push_back(Tree::build(c.path, options));
    return n;
}

bool NarrowPhase::operator()(int a, const Placement& pa, int b, const Placement& pb, QueryStats* stats) const {
    if (!trees_.empty()) return collide(trees_[std::size_t(a)], pa, trees_[std::size_t(b)], pb, stats);
    return collide_sweep(index_[std::size_t(a)], pa, index_[std::size_t(b)], pb);
}

bool NarrowPhase::operator()(int a, const Placement& pa, const Rigid2& ma, int b, const Placement& pb, const Rigid2& mb,
                             QueryStats* stats) const {
    if (!trees_.empty()) return collide(trees_[std::size_t(a)], pa, trees_[std::size_t(b)], pb, stats);
    return collide_sweep(index_[std::size_t(a)], pa, ma, index_[std::size_t(b)], pb, mb);
}

const char* NarrowPhase::name() const { return trees_.empty() ? "sweep" : to_string(trees_.front().options().type); }

}  // namespace mobb::crowd
