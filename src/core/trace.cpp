#include "mobb/core/trace.h"

namespace mobb {

std::vector<int> tests_per_node(const Trace& trace, bool side_a, std::size_t nodes) {
    std::vector<int> out(nodes, 0);
    for (const TraceEvent& e : trace) {
        if (e.test == TraceTest::Descend) continue;
        const std::int32_t n = side_a ? e.node_a : e.node_b;
        if (n >= 0 && std::size_t(n) < nodes) ++out[std::size_t(n)];
    }
    return out;
}

const char* to_string(TraceTest test) {
    switch (test) {
        case TraceTest::Time: return "time";
        case TraceTest::Box2: return "box2d";
        case TraceTest::Box3: return "box3d";
        case TraceTest::Descend: return "descend";
        case TraceTest::Samples: return "samples";
    }
    return "?";
}

const char* to_string(TraceOutcome outcome) {
    switch (outcome) {
        case TraceOutcome::NoTimeOverlap: return "no time overlap";
        case TraceOutcome::Separated: return "separated";
        case TraceOutcome::Overlap: return "overlap";
        case TraceOutcome::Miss: return "miss";
        case TraceOutcome::Hit: return "hit";
    }
    return "?";
}

}  // namespace mobb
