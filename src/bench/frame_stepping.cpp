#include "frame_stepping.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace mobb::bench {

using crowd::AgentTrack;
using crowd::Candidate;
using crowd::ChoicePoint;
using crowd::GraphClip;
using crowd::MotionGraph;
using crowd::PlacedClip;
using crowd::Record;

namespace {

using Clock = std::chrono::steady_clock;

struct Entry {
    std::int64_t ix, iy;
    int agent;
    bool operator<(const Entry& o) const { return ix != o.ix ? ix < o.ix : iy != o.iy ? iy < o.iy : agent < o.agent; }
};

// Every agent's disk at every frame its clips cover, and the choice point that took the clip (its index is
// the order of the commits), from the clips themselves.
struct Positions {
    std::int64_t frames = 0;
    std::vector<Sample> disk;          // [agent * frames + f]
    std::vector<std::int64_t> choice;  // same layout; -1 where no clip
};

Positions positions(const MotionGraph& g, const Record& r) {
    Positions p;
    for (const AgentTrack& t : r.tracks)
        for (const PlacedClip& c : t.clips)
            p.frames = std::max(p.frames, c.start + std::int64_t(g.clips[std::size_t(c.clip)].path.size()));
    const std::size_t n = r.tracks.size() * std::size_t(p.frames);
    p.disk.assign(n, {});
    p.choice.assign(n, -1);
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (const PlacedClip& c : r.tracks[a].clips) {
            const Rigid2 m = Rigid2::of(c.place);
            const Path& path = g.clips[std::size_t(c.clip)].path;
            for (std::size_t i = 0; i < path.size(); ++i) {
                const Sample& s = path.samples[i];
                const std::size_t at = a * std::size_t(p.frames) + std::size_t(c.start) + i;
                p.disk[at] = {m.apply_x(s.x, s.y), m.apply_y(s.x, s.y), s.r};
                p.choice[at] = c.choice;
            }
        }
    return p;
}

}  // namespace

FrameSteppingResult frame_stepping(const MotionGraph& g, const Record& r) {
    FrameSteppingResult out;
    const Positions pos = positions(g, r);
    const std::size_t agents = r.tracks.size();
    double rmax = 0;
    for (const GraphClip& c : g.clips)
        for (const Sample& s : c.path.samples) rmax = std::max(rmax, s.r);
    const double cell = std::max(2.0 * rmax, 1e-3);
    auto cell_of = [&](double v) { return std::int64_t(std::floor(v / cell)); };

    // One sorted grid per frame, as a frame-stepping simulator keeps up to date while it steps.
    const auto t0 = Clock::now();
    std::vector<Entry> grid;
    std::vector<std::size_t> offset(std::size_t(pos.frames) + 1, 0);
    grid.reserve(agents * std::size_t(pos.frames));
    for (std::int64_t f = 0; f < pos.frames; ++f) {
        const std::size_t begin = grid.size();
        for (std::size_t a = 0; a < agents; ++a) {
            const std::size_t at = a * std::size_t(pos.frames) + std::size_t(f);
            if (pos.choice[at] < 0) continue;
            grid.push_back({cell_of(pos.disk[at].x), cell_of(pos.disk[at].y), int(a)});
        }
        std::sort(grid.begin() + std::ptrdiff_t(begin), grid.end());
        offset[std::size_t(f) + 1] = grid.size();
    }
    const auto t1 = Clock::now();

    std::vector<Placement> placement_of(r.choices.size());
    for (const AgentTrack& t : r.tracks)
        for (const PlacedClip& c : t.clips) placement_of[std::size_t(c.choice)] = c.place;
    for (std::size_t ci = 0; ci < r.choices.size(); ++ci) {
        const ChoicePoint& cp = r.choices[ci];
        const Rigid2 m = Rigid2::of(placement_of[ci]);
        for (const Candidate& cand : cp.candidates) {
            ++out.candidates;
            const Path& path = g.clips[std::size_t(cand.clip)].path;
            bool hit = false;
            for (std::size_t i = 0; i < path.size() && !hit; ++i) {
                const std::int64_t f = cp.frame + std::int64_t(i);
                if (f >= pos.frames) break;
                const Sample& s = path.samples[i];
                const double x = m.apply_x(s.x, s.y), y = m.apply_y(s.x, s.y);
                const auto first = grid.begin() + std::ptrdiff_t(offset[std::size_t(f)]);
                const auto last = grid.begin() + std::ptrdiff_t(offset[std::size_t(f) + 1]);
                const std::int64_t ix = cell_of(x), iy = cell_of(y);
                for (std::int64_t dx = -1; dx <= 1 && !hit; ++dx)
                    for (std::int64_t dy = -1; dy <= 1 && !hit; ++dy)
                        for (auto it = std::lower_bound(first, last, Entry{ix + dx, iy + dy, -1});
                             it != last && it->ix == ix + dx && it->iy == iy + dy; ++it) {
                            const std::size_t at = std::size_t(it->agent) * std::size_t(pos.frames) + std::size_t(f);
                            if (it->agent == cp.agent || pos.choice[at] >= std::int64_t(ci)) continue;
                            ++out.disk_tests;
                            const Sample& o = pos.disk[at];
                            const double ddx = x - o.x, ddy = y - o.y, rr = s.r + o.r;
                            if (ddx * ddx + ddy * ddy < rr * rr) {
                                hit = true;
                                break;
                            }
                        }
            }
            if (hit) ++out.positive;
            if (hit != (cand.hits > 0)) {
                ++out.disagreements;
                ++(hit ? out.only_stepping : out.only_queries);
            }
        }
    }
    const auto t2 = Clock::now();
    out.build_seconds = std::chrono::duration<double>(t1 - t0).count();
    out.check_seconds = std::chrono::duration<double>(t2 - t1).count();
    return out;
}

}  // namespace mobb::bench
