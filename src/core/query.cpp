#include "mobb/core/query.h"
#include "mobb/core/assert.h"

#include <cmath>

namespace mobb {

namespace {

// Observers decide at compile time what a query records: nothing, counters, or counters + trace.
struct Silent {
    void box(BoxKind) {}
    void samples(std::uint64_t) {}
    void event(const TraceEvent&) {}
};

struct Counting {
    QueryStats& stats;
    void box(BoxKind kind) { ++(kind == BoxKind::Box2 ? stats.tests2d : stats.tests3d); }
    void samples(std::uint64_t n) { stats.samples += n; }
    void event(const TraceEvent&) {}
};

struct Tracing : Counting {
    Trace& trace;
    void event(const TraceEvent& e) { trace.push_back(e); }
};

// B's local space-time frame expressed in A's: rotation by theta_b - theta_a, then shift.
SpaceTimeRigid relative(const Placement& pa, const Placement& pb) {
    const double ca = std::cos(pa.theta), sa = std::sin(pa.theta);
    const double dx = pb.x - pa.x, dy = pb.y - pa.y;
    SpaceTimeRigid m;
    m.c = std::cos(pb.theta - pa.theta);
    m.s = std::sin(pb.theta - pa.theta);
    m.shift = {ca * dx + sa * dy, -sa * dx + ca * dy, pb.t0 - pa.t0};
    return m;
}

template <class Observer>
class Query {
public:
    Query(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb, Observer& obs)
        : a_(a), b_(b), pa_(pa), pb_(pb), ta_(Rigid2::of(pa)), tb_(Rigid2::of(pb)), rel_(relative(pa, pb)), obs_(obs) {}

    bool run() { return pair(0, 0); }
    SamplePair hit() const { return hit_; }

private:
    const Node& na(int i) const { return a_.nodes()[std::size_t(i)]; }
    const Node& nb(int i) const { return b_.nodes()[std::size_t(i)]; }

    bool time_overlap(const Node& x, const Node& y) const {
        const double dta = a_.path().dt, dtb = b_.path().dt;
        return times_overlap(sample_time(pa_, dta, x.first), sample_time(pa_, dta, x.end),
                             sample_time(pb_, dtb, y.first), sample_time(pb_, dtb, y.end));
    }

    bool boxes_overlap(const Node& x, const Node& y) {
        if (x.kind == BoxKind::Box2 && y.kind == BoxKind::Box2) {
            obs_.box(BoxKind::Box2);
            return overlap(a_.box2s()[x.box], transformed(b_.box2s()[y.box], rel_));
        }
        // Mixed pairs test soundly as 3D: a 2D node is its box extruded over its time range.
        obs_.box(BoxKind::Box3);
        return overlap(a_.box3(x), transformed(b_.box3(y), rel_));
    }

    // Section 3.2: time first, then space, then recurse.
    bool pair(int ia, int ib) {
        const Node& x = na(ia);
        const Node& y = nb(ib);
        if (!time_overlap(x, y)) {
            obs_.event({ia, ib, TraceTest::Time, TraceOutcome::NoTimeOverlap});
            return false;
        }
        const bool both2 = x.kind == BoxKind::Box2 && y.kind == BoxKind::Box2;
        const TraceTest test = both2 ? TraceTest::Box2 : TraceTest::Box3;
        if (!boxes_overlap(x, y)) {
            obs_.event({ia, ib, test, TraceOutcome::Separated});
            return false;
        }
        obs_.event({ia, ib, test, TraceOutcome::Overlap});
        if (x.leaf() && y.leaf()) return leaves(ia, ib);
        if (x.leaf()) return descend_b(ia, ib);
        if (y.leaf()) return descend_a(ia, ib);
        for (int i = x.child; i <= x.child + 1; ++i)
            for (int j = y.child; j <= y.child + 1; ++j)
                if (pair(i, j)) return true;
        return false;
    }

    // Figure 4: a leaf against an inner node picks children by time only, no spatial test.
    bool descend_b(int leaf, int inner) {
        for (int j = nb(inner).child; j <= nb(inner).child + 1; ++j) {
            if (!descend_step(leaf, j, time_overlap(na(leaf), nb(j)))) continue;
            if (nb(j).leaf() ? leaves(leaf, j) : descend_b(leaf, j)) return true;
        }
        return false;
    }

    bool descend_a(int inner, int leaf) {
        for (int i = na(inner).child; i <= na(inner).child + 1; ++i) {
            if (!descend_step(i, leaf, time_overlap(na(i), nb(leaf)))) continue;
            if (na(i).leaf() ? leaves(i, leaf) : descend_a(i, leaf)) return true;
        }
        return false;
    }

    bool descend_step(int ia, int ib, bool overlaps) {
        obs_.event({ia, ib, TraceTest::Descend, overlaps ? TraceOutcome::Overlap : TraceOutcome::NoTimeOverlap});
        return overlaps;
    }

    bool leaves(int ia, int ib) {
        const Node& x = na(ia);
        const Node& y = nb(ib);
        std::uint64_t tested = 0;
        const bool found =
            leaf_test(a_.path(), pa_, ta_, x.first, x.end, b_.path(), pb_, tb_, y.first, y.end, tested, hit_);
        obs_.samples(tested);
        TraceEvent e{ia, ib, TraceTest::Samples, found ? TraceOutcome::Hit : TraceOutcome::Miss};
        if (found) e.sample_a = std::int32_t(hit_.a), e.sample_b = std::int32_t(hit_.b);
        e.samples_tested = std::uint32_t(tested);
        obs_.event(e);
        return found;
    }

    const Tree& a_;
    const Tree& b_;
    const Placement& pa_;
    const Placement& pb_;
    Rigid2 ta_, tb_;
    SpaceTimeRigid rel_;
    Observer& obs_;
    SamplePair hit_;
};

template <class Observer>
bool run(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb, Observer& obs, SamplePair* hit) {
    Query<Observer> q(a, pa, b, pb, obs);
    const bool found = q.run();
    if (hit) *hit = found ? q.hit() : SamplePair{};
    return found;
}

// First k in [lo, hi) with sample_time(p, dt, k + 1) > t: samples before it end at or before t.
std::int64_t first_ending_after(const Placement& p, double dt, std::int64_t lo, std::int64_t hi, double t) {
    while (lo < hi) {
        const std::int64_t mid = lo + (hi - lo) / 2;
        if (sample_time(p, dt, mid + 1) > t)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

}  // namespace

bool leaf_test(const Path& a, const Placement& pa, const Rigid2& ta, std::int64_t fa, std::int64_t ea, const Path& b,
               const Placement& pb, const Rigid2& tb, std::int64_t fb, std::int64_t eb, std::uint64_t& tested,
               SamplePair& hit) {
    MOBB_ASSERT(0 <= fa && fa <= ea && std::size_t(ea) <= a.samples.size());
    MOBB_ASSERT(0 <= fb && fb <= eb && std::size_t(eb) <= b.samples.size());
    const double b_end = sample_time(pb, b.dt, eb);
    std::int64_t i = first_ending_after(pa, a.dt, fa, ea, sample_time(pb, b.dt, fb));
    if (i >= ea) return false;
    std::int64_t j = first_ending_after(pb, b.dt, fb, eb, sample_time(pa, a.dt, i));
    for (; i < ea; ++i) {
        const double s0 = sample_time(pa, a.dt, i), s1 = sample_time(pa, a.dt, i + 1);
        if (s0 >= b_end) break;
        while (j < eb && sample_time(pb, b.dt, j + 1) <= s0) ++j;
        for (std::int64_t k = j; k < eb && sample_time(pb, b.dt, k) < s1; ++k) {
            ++tested;
            if (samples_overlap(ta, a.samples[std::size_t(i)], tb, b.samples[std::size_t(k)])) {
                hit = {i, k};
                return true;
            }
        }
    }
    return false;
}

bool collide(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb, QueryStats* stats, Trace* trace,
             SamplePair* hit) {
    if (trace) {
        trace->clear();
        QueryStats local;
        Tracing obs{{stats ? *stats : local}, *trace};
        return run(a, pa, b, pb, obs, hit);
    }
    if (stats) {
        Counting obs{*stats};
        return run(a, pa, b, pb, obs, hit);
    }
    Silent obs;
    return run(a, pa, b, pb, obs, hit);
}

}  // namespace mobb
