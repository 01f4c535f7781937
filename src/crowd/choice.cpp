#include "choice.h"

#include <algorithm>
#include <stdexcept>

#include "mobb/util/random.h"

namespace mobb::crowd {

namespace {

// How far a point is outside the world rectangle (0 inside), metres.
double excursion(double x, double y, const CrowdOptions& o) {
    return std::max({0.0, -x, x - o.width, -y, y - o.height});
}

}  // namespace

ClipOutline outline_of(const Path& path) {
    ClipOutline out;
    std::vector<std::array<double, 2>> pts;
    for (const Sample& s : path.samples) {
        pts.push_back({s.x, s.y});
        out.r_max = std::max(out.r_max, s.r);
    }
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) {
        out.hull = pts;
        return out;
    }
    // Andrew's monotone chain: lower hull, then upper hull.
    auto cross = [](const auto& o, const auto& a, const auto& b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    };
    std::vector<std::array<double, 2>>& h = out.hull;
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t floor = h.size();
        for (const auto& q : pts) {
            while (h.size() >= floor + 2 && cross(h[h.size() - 2], h.back(), q) <= 0) h.pop_back();
            h.push_back(q);
        }
        h.pop_back();  // the next chain starts with it
        std::reverse(pts.begin(), pts.end());
    }
    return out;
}

std::vector<ClipOutline> outlines_of(const MotionGraph& g) {
    std::vector<ClipOutline> out;
    for (const GraphClip& c : g.clips) out.push_back(outline_of(c.path));
    return out;
}

// A candidate "leaves the world" when its root goes farther outside the rectangle than where it
// starts, so an agent pushed out by a fallback may walk back in.
Placed place_clip(const ClipOutline& outline, int clip, std::int64_t frames, const Placement& p, std::int64_t frame,
                  const CrowdOptions& o) {
    Placed out{clip, p, {}, false, 0.0};
    const Rigid2 m = Rigid2::of(p);
    out.box = {1e300, 1e300, -1e300, -1e300, frame, frame + frames};
    const double start = excursion(p.x, p.y, o);
    for (const auto& v : outline.hull) {
        const double x = m.apply_x(v[0], v[1]), y = m.apply_y(v[0], v[1]);
        out.box.x0 = std::min(out.box.x0, x);
        out.box.y0 = std::min(out.box.y0, y);
        out.box.x1 = std::max(out.box.x1, x);
        out.box.y1 = std::max(out.box.y1, y);
        out.excess = std::max(out.excess, excursion(x, y, o) - start);
    }
    out.box.x0 -= outline.r_max;
    out.box.y0 -= outline.r_max;
    out.box.x1 += outline.r_max;
    out.box.y1 += outline.r_max;
    out.outside = out.excess > 0;
    return out;
}

void Choice::prepare(const CrowdState& s, int agent, std::int64_t frame) {
    agent_ = agent;
    frame_ = frame;
    util::Random rng = util::Random::stream(s.options.seed, std::uint64_t(agent), std::uint64_t(frame));
    const Agent& a = s.agents[std::size_t(agent)];
    const MotionGraph& g = s.graph;
    std::vector<int>& order = order_;
    base_ = a.start;
    if (a.clips.empty()) {
        order = g.clips[std::size_t(rng.below(int(g.clips.size())))].successors;
    } else {
        const PlacedClip& last = a.clips.back();
        order = g.clips[std::size_t(last.clip)].successors;
        base_ = g.next(last.place, last.clip);
    }
    if (order.empty()) throw std::invalid_argument("crowd: a graph clip has no successors");
    base_.t0 = double(frame) * g.dt();  // on the global grid, not accumulated
    for (std::size_t k = order.size(); k > 1; --k) std::swap(order[k - 1], order[std::size_t(rng.below(int(k)))]);
    random_pick_ = rng.below(int(order.size()));
    placed_.clear();
    near_.resize(order.size());
    asked_.resize(order.size());
    for (auto& v : asked_) v.clear();
    queried_ = 0;
}

const Placed& Choice::place(const CrowdState& s, int k) {
    while (int(placed_.size()) <= k) {
        const int clip = order_[placed_.size()];
        placed_.push_back(place_clip(s.outlines[std::size_t(clip)], clip,
                                     std::int64_t(s.graph.clips[std::size_t(clip)].path.size()), base_, frame_,
                                     s.options));
    }
    return placed_[std::size_t(k)];
}

const Answer& Choice::ask(const CrowdState& s, int k, std::size_t pos, int id) {
    std::vector<Answer>& asked = asked_[std::size_t(k)];
    if (pos < asked.size() && asked[pos].id == id) return asked[pos];
    const Committed& other = s.committed[std::size_t(id)];
    const Placed& c = placed_[std::size_t(k)];
    Answer a{id, false, {}};
    a.hit = collide(s.trees[std::size_t(c.clip)], c.place, s.trees[std::size_t(other.clip)], other.place, &a.stats);
    // Lists only grow at their end, so the answer belongs at `pos` (anything else is not kept).
    asked.resize(std::min(asked.size(), pos));
    asked.push_back(a);
    return asked.back();
}

int Choice::count_hits(const CrowdState& s, int k, bool stop_at_hit) {
    Candidate& cand = point_.candidates[std::size_t(k)];
    cand.queries = 0;  // a fallback reruns a candidate's queries in full: keep only the full list
    cand.against.clear();
    int hits = 0;
    const std::vector<int>& near = near_[std::size_t(k)];
    for (std::size_t pos = 0; pos < near.size(); ++pos) {
        const Answer& a = ask(s, k, pos, near[pos]);
        const Committed& other = s.committed[std::size_t(a.id)];
        ++cand.queries;
        cand.against.push_back({other.agent, other.index, a.hit});
        ++point_.queries;
        point_.tests2d += a.stats.tests2d;
        point_.tests3d += a.stats.tests3d;
        point_.samples += a.stats.samples;
        if (!a.hit && a.stats.tests2d + a.stats.tests3d <= 1 && a.stats.samples == 0) ++root_rejected_;
        if (s.options.log_queries) log_.emplace_back(k, a);
        if (a.hit) {
            ++hits;
            if (stop_at_hit) break;
        }
    }
    cand.hits = hits;
    return hits;
}

// Every candidate failed: the fewest collisions, then the least far out.
int Choice::fallback_pick() const {
    int taken = 0;
    for (std::size_t k = 1; k < placed_.size(); ++k) {
        const Candidate &x = point_.candidates[k], &y = point_.candidates[std::size_t(taken)];
        if (std::make_pair(x.hits, placed_[k].excess) < std::make_pair(y.hits, placed_[std::size_t(taken)].excess))
            taken = int(k);
    }
    return taken;
}

void Choice::evaluate(const CrowdState& s) {
    point_ = ChoicePoint{};
    point_.agent = agent_;
    point_.frame = frame_;
    point_.candidates.reserve(order_.size());
    queried_ = 0;
    taken_ = -1;
    root_rejected_ = 0;
    log_.clear();
    const bool random = s.options.select == Selection::Random;
    for (int k = 0; k < int(order_.size()); ++k) {
        const Placed& c = place(s, k);
        point_.candidates.push_back({c.clip, c.outside, 0, 0, {}});
        s.broad.query(c.box, agent_, near_[std::size_t(k)]);
        queried_ = k + 1;
        if (!random && c.outside) continue;  // dropped without queries
        if (count_hits(s, k, !random) == 0 && !random) {
            taken_ = k;
            break;
        }
    }
    if (random) {
        taken_ = random_pick_;
    } else if (taken_ < 0) {  // every candidate failed: count all collisions
        point_.fallback = true;
        for (int k = 0; k < int(placed_.size()); ++k) count_hits(s, k, false);
        taken_ = fallback_pick();
    }
    point_.taken = placed_[std::size_t(taken_)].clip;
}

bool Choice::affected_by(const BatchGrid& chosen, int below) const {
    for (int k = 0; k < queried_; ++k)
        if (chosen.any_before(placed_[std::size_t(k)].box, below)) return true;
    return false;
}

bool Choice::affected_by(const SpaceTimeBox& box) const {
    for (int k = 0; k < queried_; ++k)
        if (placed_[std::size_t(k)].box.overlaps(box)) return true;
    return false;
}

std::uint64_t Choice::near_total() const {
    std::uint64_t n = 0;
    for (int k = 0; k < queried_; ++k) n += near_[std::size_t(k)].size();
    return n;
}

}  // namespace mobb::crowd
