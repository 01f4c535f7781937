// The ordered record of one query, for step-through debugging (the viewer replays it).
#pragma once
#include <cstdint>
#include <vector>

namespace mobb {

enum class TraceTest : std::uint8_t {
    Time,     ///< temporal overlap of two nodes' time ranges (paper 3.2)
    Box2,     ///< 2D separating-axis test (4 axes)
    Box3,     ///< 3D separating-axis test (15 axes)
    Descend,  ///< leaf against inner node: child chosen by time only (paper figure 4)
    Samples,  ///< leaf against leaf: sample pairs whose time intervals overlap
};

enum class TraceOutcome : std::uint8_t {
    NoTimeOverlap,  ///< pruned in time
    Separated,      ///< pruned in space
    Overlap,        ///< overlap: recurse
    Miss,           ///< leaf sample tests found no collision
    Hit,            ///< collision: sample_a and sample_b collide
};

/// One step: which two nodes (indices into each tree's nodes()), which test, what outcome.
struct TraceEvent {
    std::int32_t node_a = -1, node_b = -1;
    TraceTest test = TraceTest::Time;
    TraceOutcome outcome = TraceOutcome::Overlap;
    std::int32_t sample_a = -1, sample_b = -1;  ///< the colliding pair, for Hit
    std::uint32_t samples_tested = 0;           ///< sample tests of a Samples event
};

using Trace = std::vector<TraceEvent>;

/// How often a query tested each node of one of its trees: events naming the node (node_a for
/// side A, node_b for side B), descents excluded; `nodes` entries (that tree's node count).
std::vector<int> tests_per_node(const Trace& trace, bool side_a, std::size_t nodes);

const char* to_string(TraceTest test);
const char* to_string(TraceOutcome outcome);

}  // namespace mobb
