#include "recursion.h"

namespace mobb::viewer {

namespace {

/// Whether `node` is `parent` or one of its two children.
bool same_or_child(const Tree& tree, std::int32_t parent, std::int32_t node) {
    if (node == parent) return true;
    if (parent < 0 || parent >= std::int32_t(tree.nodes().size())) return false;
    const Node& p = tree.nodes()[std::size_t(parent)];
    return !p.leaf() && (node == p.child || node == p.child + 1);
}

}  // namespace

Recursion recursion_of(const Trace& trace, const Tree& a, const Tree& b) {
    Recursion r;
    std::vector<int> open;  // pairs that recursed, innermost last
    for (int e = 0; e < int(trace.size()); ++e) {
        const TraceEvent& ev = trace[std::size_t(e)];
        if (!r.pairs.empty()) {
            NodePair& last = r.pairs.back();
            if (last.node_a == ev.node_a && last.node_b == ev.node_b && last.end == e &&
                trace[std::size_t(e - 1)].outcome == TraceOutcome::Overlap) {
                last.end = e + 1;  // the next test of the same pair
                last.outcome = ev.outcome;
                r.pair_of.push_back(int(r.pairs.size()) - 1);
                if (ev.outcome == TraceOutcome::Hit && r.first_hit < 0) r.first_hit = e;
                continue;
            }
            if (last.outcome == TraceOutcome::Overlap) open.push_back(int(r.pairs.size()) - 1);
        }
        while (!open.empty()) {
            const NodePair& p = r.pairs[std::size_t(open.back())];
            if (same_or_child(a, p.node_a, ev.node_a) && same_or_child(b, p.node_b, ev.node_b) &&
                !(p.node_a == ev.node_a && p.node_b == ev.node_b))
                break;
            open.pop_back();
        }
        NodePair n;
        n.node_a = ev.node_a, n.node_b = ev.node_b;
        n.first = e, n.end = e + 1;
        n.outcome = ev.outcome;
        n.parent = open.empty() ? -1 : open.back();
        r.pairs.push_back(n);
        r.pair_of.push_back(int(r.pairs.size()) - 1);
        if (ev.outcome == TraceOutcome::Hit && r.first_hit < 0) r.first_hit = e;
    }
    for (int k = int(r.pairs.size()) - 1; k >= 0; --k) {  // children come after their parents
        NodePair& p = r.pairs[std::size_t(k)];
        p.events += p.end - p.first;
        p.hit = p.hit || p.outcome == TraceOutcome::Hit;
        if (p.parent < 0) continue;
        NodePair& up = r.pairs[std::size_t(p.parent)];
        up.events += p.events;
        up.hit = up.hit || p.hit;
    }
    for (int k = 0; k < int(r.pairs.size()); ++k)
        if (r.pairs[std::size_t(k)].parent >= 0)
            r.pairs[std::size_t(r.pairs[std::size_t(k)].parent)].children.push_back(k);
    return r;
}

std::vector<int> events_holding(const Trace& trace, const Tree& tree, int side, std::int64_t sample) {
    std::vector<int> out;
    const auto& nodes = tree.nodes();
    for (int e = 0; e < int(trace.size()); ++e) {
        const std::int32_t id = side == 0 ? trace[std::size_t(e)].node_a : trace[std::size_t(e)].node_b;
        if (id < 0 || id >= std::int32_t(nodes.size())) continue;
        const Node& n = nodes[std::size_t(id)];
        if (sample >= std::int64_t(n.first) && sample < std::int64_t(n.end)) out.push_back(e);
    }
    return out;
}

std::vector<int> events_of_node(const Trace& trace, int side, std::int32_t node) {
    std::vector<int> out;
    for (int e = 0; e < int(trace.size()); ++e)
        if ((side == 0 ? trace[std::size_t(e)].node_a : trace[std::size_t(e)].node_b) == node) out.push_back(e);
    return out;
}

}  // namespace mobb::viewer
