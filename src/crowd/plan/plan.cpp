// The state a choice point reads (crowd_state.h): plans placed along escape routes, and the exact tests
// of their pieces against the solids and the others' pieces.
#include "plan/crowd_state.h"

#include <algorithm>
#include <cmath>

namespace mobb::crowd {

namespace {

// A clip's samples against held ground: a sample covering frames [f, f + 1) overlaps the held disk when
// f + 1 > the hold's first frame (integer frames: the global grid, exact) and the disks overlap. Blocks
// of samples whose circle stays a millimetre clear of the disk are skipped (the exact test decides).
bool clip_meets_hold(const MotionGraph& g, const ClipOutline& outline, const BoxedClip& c, const Hold& h,
                     QueryStats* stats) {
    const Path& path = g.clips[std::size_t(c.clip)].path;
    const Rigid2& m = c.m;
    const Rigid2 still{1, 0, 0, 0};
    const Sample disk{h.x, h.y, h.r};
    // The hold's centre in the clip's frame.
    const double dx = h.x - m.tx, dy = h.y - m.ty, hx = m.c * dx + m.s * dy, hy = -m.s * dx + m.c * dy;
    const auto n = std::int64_t(path.size()), block = std::int64_t(ClipOutline::kBlock);
    for (std::int64_t i = std::max<std::int64_t>(0, h.frame - c.frame); i < n;) {
        const auto& b = outline.blocks[std::size_t(i / block)];
        const std::int64_t end = std::min(n, (i / block + 1) * block);
        const double reach = b[2] + h.r + 1e-3;
        if ((b[0] - hx) * (b[0] - hx) + (b[1] - hy) * (b[1] - hy) >= reach * reach) {
            i = end;
            continue;
        }
        for (; i < end; ++i) {
            if (stats) ++stats->samples;
            if (samples_overlap(m, path.samples[std::size_t(i)], still, disk)) return true;
        }
    }
    return false;
}

}  // namespace

std::array<double, 2> clip_end(const MotionGraph& g, int clip, const Placement& place) {
    const Sample& s = g.clips[std::size_t(clip)].path.samples.back();
    const Rigid2 m = Rigid2::of(place);
    return {m.apply_x(s.x, s.y), m.apply_y(s.x, s.y)};
}

bool reaches_goal(const std::array<double, 2>& p, const std::array<double, 2>& goal, double radius) {
    return std::hypot(p[0] - goal[0], p[1] - goal[1]) < radius;
}

BoxedClip frame_clip(const CrowdState& s, int clip, const Placement& p, const Rigid2& m, std::int64_t frame) {
    const std::int64_t frames = std::int64_t(s.graph.clips[std::size_t(clip)].path.size());
    return {clip, p, frame, place_clip(s.outlines[std::size_t(clip)], clip, frames, p, m, frame, nullptr).box, m};
}

Plan plan_along(const CrowdState& s, const BoxedClip& c, const std::vector<int>& route) {
    Plan plan;
    build_plan(s, c, route, plan, [](const Piece&) { return true; });
    return plan;
}

bool pieces_collide(const CrowdState& s, const Piece& mine, const Piece& other, QueryStats* stats) {
    if (mine.kind == Piece::Clip && other.kind == Piece::Clip) {
        const BoxedClip &a = mine.clip, &b = other.clip;
        return s.narrow(a.clip, a.place, a.m, b.clip, b.place, b.m, stats);
    }
    if (mine.kind == Piece::Clip)
        return clip_meets_hold(s.graph, s.outlines[std::size_t(mine.clip.clip)], mine.clip, other.hold, stats);
    if (other.kind == Piece::Clip)
        return clip_meets_hold(s.graph, s.outlines[std::size_t(other.clip.clip)], other.clip, mine.hold, stats);
    return holds_meet(mine.hold, other.hold);
}

void query_pieces(const CrowdState& s, const SpaceTimeBox& box, int owner, std::vector<int>& out) {
    s.broad.query(box, owner, out, false);  // ordered here, by seq
    if (out.size() < 2) return;
    const std::vector<Piece>& p = s.pieces;
    std::sort(out.begin(), out.end(), [&](int a, int b) { return p[std::size_t(a)].seq < p[std::size_t(b)].seq; });
}

bool meets_solid(const CrowdState& s, const Piece& mine, int k) {
    const Polygon& solid = s.solids[std::size_t(k)];
    // Held ground keeps CrowdState::hold_clearance from the walls: room to stand there, or to turn round.
    if (mine.kind == Piece::Held) return disk_overlaps(solid, mine.hold.x, mine.hold.y, s.hold_clearance);
    const BoxedClip& c = mine.clip;
    return path_hits(s.graph.clips[std::size_t(c.clip)].path, c.m, solid);
}

}  // namespace mobb::crowd
