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

/// The same takes with each disk the smallest holding the body (`mobb graph build --centre enclosing`).
inline const std::string kBodyCentredGraph =
    std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion_enclosing.json";

inline const crowd::MotionGraph& body_centred_graph() {
    static const crowd::MotionGraph g = crowd::load_graph(kBodyCentredGraph);
    return g;
}

}  // namespace mobb::test
