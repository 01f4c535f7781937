#include "plan/escape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mobb/crowd/tuning.h"

namespace mobb::crowd {

namespace {

// Footprint of a path in its own frame: how far any disk reaches from the first root position, the origin
// (the first disk's centre too when disks are centred on the root).
double footprint_of(const Path& p) {
    double f = 0;
    for (const Sample& s : p.samples) f = std::max(f, std::hypot(s.x, s.y) + s.r);
    return f;
}

// Steps from each clip to an idle clip through successors (1: a successor is idle), by a breadth-first
// search backwards from the idle clips; -1 where none is reachable.
std::vector<int> steps_to_idle(const MotionGraph& g, const std::vector<ClipKind>& kind) {
    const int n = int(g.clips.size());
    std::vector<std::vector<int>> before(static_cast<std::size_t>(n));
    for (int c = 0; c < n; ++c)
        for (int s : g.clips[std::size_t(c)].successors) before[std::size_t(s)].push_back(c);
    std::vector<int> steps(std::size_t(n), -1), queue;
    for (int c = 0; c < n; ++c)
        if (kind[std::size_t(c)] == ClipKind::Idle)
            for (int p : before[std::size_t(c)])
                if (steps[std::size_t(p)] < 0) steps[std::size_t(p)] = 1, queue.push_back(p);
    for (std::size_t k = 0; k < queue.size(); ++k)
        for (int p : before[std::size_t(queue[k])])
            if (steps[std::size_t(p)] < 0) steps[std::size_t(p)] = steps[std::size_t(queue[k])] + 1, queue.push_back(p);
    return steps;
}

// Chains of exactly `length` clips from `clip` to an idle clip, in successor order, until `out` holds
// max_routes: each step goes to a successor from which an idle clip is still in reach.
void routes_from(const MotionGraph& g, const std::vector<ClipKind>& kind, const std::vector<int>& steps, int clip,
                 int length, int max_routes, std::vector<int>& chain, std::vector<std::vector<int>>& out) {
    for (int s : g.clips[std::size_t(clip)].successors) {
        if (int(out.size()) >= max_routes) return;
        const bool idle = kind[std::size_t(s)] == ClipKind::Idle;
        if (length == 1 ? !idle : idle || steps[std::size_t(s)] < 0 || steps[std::size_t(s)] > length - 1) continue;
        chain.push_back(s);
        if (length == 1)
            out.push_back(chain);
        else
            routes_from(g, kind, steps, s, length - 1, max_routes, chain, out);
        chain.pop_back();
    }
}

// Where route `route` after clip `clip` holds its ground, in the clip's frame: chained as the crowd places
// it (build_plan, crowd_state.h).
std::array<double, 2> route_end(const MotionGraph& g, int clip, const std::vector<int>& route) {
    Placement p;
    int prev = clip;
    for (int next : route) {
        p = g.next(p, prev);
        prev = next;
    }
    return {p.x, p.y};
}

}  // namespace

EscapeTable EscapeTable::build(const MotionGraph& g, const CrowdTuning& tuning) {
    const int max_steps = tuning.escape.steps, max_routes = tuning.escape.routes;
    if (max_routes > kMaxRoutes) throw std::invalid_argument("crowd: more escape routes per clip than kMaxRoutes");
    EscapeTable t;
    for (int c = 0; c < int(g.clips.size()); ++c) {
        const GraphClip& clip = g.clips[std::size_t(c)];
        t.kind.push_back(kind_of(clip, c));
        t.in_place.push_back(t.kind.back() == ClipKind::InPlace || t.kind.back() == ClipKind::Idle);
        t.footprint.push_back(footprint_of(clip.path));
        const double duration = double(clip.path.size()) * g.dt();
        t.moves.push_back(std::hypot(clip.exit_x, clip.exit_y) >= tuning.moving_speed * duration);
        if (t.kind.back() == ClipKind::Idle) t.hold_radius = std::max(t.hold_radius, t.hold_of(c));
    }
    for (int c = 0; c < int(g.clips.size()); ++c) {
        const double room = t.footprint[std::size_t(c)] + tuning.escape.wall_margin;
        if (t.kind[std::size_t(c)] == ClipKind::Idle) t.stand_clearance = std::max(t.stand_clearance, room);
        if (t.in_place[std::size_t(c)]) t.turn_clearance = std::max(t.turn_clearance, room);
    }
    if (t.hold_radius == 0)
        throw std::invalid_argument(
            "crowd: the motion graph has no idle clip (standing, looping in place) to stop with");
    const std::vector<int> steps = steps_to_idle(g, t.kind);
    t.routes.resize(g.clips.size());
    for (int c = 0; c < int(g.clips.size()); ++c) {
        if (steps[std::size_t(c)] < 0 || steps[std::size_t(c)] > max_steps) continue;
        std::vector<int> chain;  // the shortest routes, then those one clip longer
        for (int length = steps[std::size_t(c)]; length <= steps[std::size_t(c)] + 1 && length <= max_steps; ++length)
            routes_from(g, t.kind, steps, c, length, max_routes, chain, t.routes[std::size_t(c)]);
    }
    t.ends.resize(g.clips.size());
    for (int c = 0; c < int(g.clips.size()); ++c)
        for (const std::vector<int>& route : t.routes[std::size_t(c)])
            t.ends[std::size_t(c)].push_back(route_end(g, c, route));
    return t;
}

}  // namespace mobb::crowd
