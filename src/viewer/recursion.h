// The query's recursion rebuilt from its trace (replayed, never re-run): consecutive events on the
// same two nodes form one node pair, and a pair's parent is the nearest earlier pair that recursed
// (ended in Overlap) on the same nodes or their parents. The recursion view draws this tree.
#pragma once
#include <cstdint>
#include <vector>

#include "mobb/core/trace.h"
#include "mobb/core/tree.h"

namespace mobb::viewer {

struct NodePair {
    std::int32_t node_a = -1, node_b = -1;
    int first = 0, end = 0;  ///< its events [first, end) in the trace
    int parent = -1;         ///< index into the pairs, -1 for the root(s)
    std::vector<int> children;
    TraceOutcome outcome = TraceOutcome::Overlap;  ///< of its last event
    int events = 0;                                ///< events of the pair and everything below it
    bool hit = false;                              ///< a Hit in it or below it
};

struct Recursion {
    std::vector<NodePair> pairs;  ///< in trace order (parents before children)
    std::vector<int> pair_of;     ///< for each event, its pair
    int first_hit = -1;           ///< the first Hit event, -1 for none
};

/// The recursion of a trace of collide(a, ...) against b.
Recursion recursion_of(const Trace& trace, const Tree& a, const Tree& b);

/// Events whose node of clip side `side` (0 = A, 1 = B) holds `sample`, in trace order.
std::vector<int> events_holding(const Trace& trace, const Tree& tree, int side, std::int64_t sample);

/// Events on node `node` of clip side `side` (0 = A, 1 = B), in trace order.
std::vector<int> events_of_node(const Trace& trace, int side, std::int32_t node);

}  // namespace mobb::viewer
