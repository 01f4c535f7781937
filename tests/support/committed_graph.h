// The committed motion graph (assets/graphs/cmu_locomotion.json) for crowd tests, read once per test
// binary. Needs MOBB_SOURCE_DIR and mobb_crowd.
#pragma once
#include <string>

#include "mobb/crowd/graph/motion_graph.h"

namespace mobb::test {

inline const std::string kCommittedGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

inline const crowd::MotionGraph& committed_graph() {
    static const crowd::MotionGraph g = crowd::load_graph(kCommittedGraph);
    return g;
}

}  // namespace mobb::test
