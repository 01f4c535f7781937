#include "sim/frame_stream.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mobb/core/assert.h"

namespace mobb::crowd {

namespace {

using Clock = std::chrono::steady_clock;

// The disk about an agent's disks of a window (`count` of them, `stride` apart; NaN where it is not in
// the run), a little wider than the exact bound so that rounding never leaves one of them outside; radius
// -1 when it is in none.
FrameGrid::Disk sweep(const std::array<double, 4>* disks, std::size_t stride, std::int64_t count, int agent) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, r = -1;
    for (std::int64_t k = 0; k < count; ++k) {
        const std::array<double, 4>& d = disks[std::size_t(k) * stride];
        if (std::isnan(d[1])) continue;
        x0 = std::min(x0, d[1]), x1 = std::max(x1, d[1]);
        y0 = std::min(y0, d[2]), y1 = std::max(y1, d[2]);
        r = std::max(r, d[3]);
    }
    if (r < 0) return {0, 0, -1, agent};
    const double half = 0.5 * std::hypot(x1 - x0, y1 - y0);
    return {0.5 * (x0 + x1), 0.5 * (y0 + y1), (half + r) * (1 + 1e-9) + 1e-9, agent};
}

}  // namespace

std::int64_t group_frames(std::size_t agents) {
    constexpr std::size_t kDisks = std::size_t{1} << 23, kFrames = 32;
    const std::int64_t block = block_frames(agents);
    const auto frames = std::int64_t(std::min(kFrames, kDisks / std::max<std::size_t>(1, agents)));
    return block * std::max<std::int64_t>(1, frames / block);
}

FrameStream::FrameStream(const MotionGraph& graph, const Record& header, RecordSink& sink, double goal_radius)
    : g_(graph),
      header_(header),
      sink_(sink),
      metrics_(header, graph, goal_radius),
      tracks_(header.tracks.size()),
      block_(block_frames(header.tracks.size())),
      group_(group_frames(header.tracks.size())),
      disks_(std::size_t(group_) * tracks_.size()),
      roots_(graph.centre == io::PathCentre::Root ? 0 : disks_.size()),
      fallback_(disks_.size()) {
    sink_.begin(header_);
}

void FrameStream::clip(int agent, const PlacedClip& clip) {
    Track& t = tracks_[std::size_t(agent)];
    if (t.clips.empty()) t.m = Rigid2::of(clip.place);
    t.clips.push_back(clip);
}

void FrameStream::left(int agent, std::int64_t frame) { tracks_[std::size_t(agent)].left = frame; }

void FrameStream::until(std::int64_t frame) {
    while (frame - next_ >= group_) emit(group_);
}

void FrameStream::finish() {
    while (next_ < header_.frames) emit(std::min(group_, header_.frames - next_));
}

// Frames next_ .. next_ + count - 1: each agent's disks, checked, measured and handed to the sink a block
// at a time.
void FrameStream::emit(std::int64_t count) {
    const auto start = Clock::now();
    util::WorkerPool one(1);
    util::WorkerPool& pool = pool_ ? *pool_ : one;
    const std::size_t n = tracks_.size();
    place(count, pool);
    find_contacts(count, pool);
    for (std::int64_t k = 0; k < count; ++k)
        count_contacts(next_ + k, &disks_[std::size_t(k) * n], &fallback_[std::size_t(k) * n], found_[std::size_t(k)]);
    metrics_.frames(next_, count, disks_.data(), roots_.empty() ? nullptr : roots_.data(), pool);
    seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
    // The sink's blocks are the record's, whatever the group: the file's time counts as the record's.
    for (std::int64_t k = 0; k < count; k += block_) {
        FrameBlock block;
        block.first = next_ + k;
        block.count = std::min(block_, count - k);
        block.agents = n;
        block.disks = &disks_[std::size_t(k) * n];
        sink_.frames(block);
    }
    next_ += count;
}

// Each agent's disk at frames next_ .. next_ + count - 1 from the clip playing then (the core's own
// transform, so the check rounds as the queries do), by agents in parallel: each reads its own track.
void FrameStream::place(std::int64_t count, util::WorkerPool& pool) {
    constexpr std::size_t kAgents = 512;  // agents per task
    const std::size_t n = tracks_.size();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    pool.for_each((n + kAgents - 1) / kAgents, [&](std::size_t task, int) {
        for (std::size_t a = task * kAgents; a < std::min(n, (task + 1) * kAgents); ++a) {
            Track& t = tracks_[a];
            for (std::int64_t k = 0; k < count; ++k) {
                const std::int64_t f = next_ + k;
                const std::size_t at = std::size_t(k) * n + a;
                if (f >= t.left) {
                    disks_[at] = {nan, nan, nan, nan};
                    fallback_[at] = 0;
                    continue;
                }
                while (t.k + 1 < t.clips.size() && t.clips[t.k + 1].start <= f) t.m = Rigid2::of(t.clips[++t.k].place);
                const PlacedClip& c = t.clips[t.k];
                const GraphClip& clip = g_.clips[std::size_t(c.clip)];
                const auto i = std::size_t(f - c.start);
                MOBB_ASSERT(f >= c.start && i < clip.path.size());  // final: its clips cover it
                const Sample& s = clip.path.samples[i];
                disks_[at] = {double(f) * g_.dt(), t.m.apply_x(s.x, s.y), t.m.apply_y(s.x, s.y), s.r};
                fallback_[at] = c.fallback;
                if (roots_.empty()) continue;
                const glm::dvec2 root = placed_root(clip, t.m, i);
                roots_[at] = {root.x, root.y};
            }
            t.clips.erase(t.clips.begin(), t.clips.begin() + std::ptrdiff_t(t.k));
            t.k = 0;
        }
    });
}

// The frame-by-frame contact check of a group (as frame_contacts does it on a whole record, frame by
// frame), a window of frames at a time: two agents' disks can meet in a window only if the disks about
// all their disks of the window do, so one grid of those gives the pairs, each tested frame by frame. By
// columns of the grid in parallel; each frame's contacts sorted by pair, so the outcome is the same for
// any number of threads. A grid per frame would sort every agent into it at every frame; this sorts them
// once a window and reads each one's disks where they lie.
void FrameStream::find_contacts(std::int64_t count, util::WorkerPool& pool) {
    // About half a second: an agent's disks of a window lie within about a metre of one another, so a
    // swept disk meets those of its few neighbours only.
    constexpr std::int64_t kWindow = 16;
    found_.resize(std::size_t(count));
    for (std::vector<Contact>& f : found_) f.clear();  // kept: their memory serves the next group
    pairs_.resize(std::size_t(pool.size()));
    for (std::int64_t first = 0; first < count; first += kWindow) {
        sweep_window(first, std::min(kWindow, count - first), pool);
        for (std::vector<Contact>& p : pairs_) {
            for (const Contact& c : p) found_[std::size_t(c.frame - next_)].push_back(c);
            p.clear();
        }
    }
    for (std::vector<Contact>& f : found_)
        std::sort(f.begin(), f.end(),
                  [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
}

// The contacts of frames [first, first + frames) of the group into pairs_.
void FrameStream::sweep_window(std::int64_t first, std::int64_t frames, util::WorkerPool& pool) {
    constexpr std::size_t kAgents = 4096;  // agents per task
    const std::size_t n = tracks_.size();
    swept_.resize(n);
    pool.for_each((n + kAgents - 1) / kAgents, [&](std::size_t task, int) {
        for (std::size_t a = task * kAgents; a < std::min(n, (task + 1) * kAgents); ++a)
            swept_[a] = sweep(&disks_[std::size_t(first) * n + a], n, frames, int(a));
    });
    in_run_.clear();
    double reach = 0;  // swept disks that meet are closer than this
    for (const FrameGrid::Disk& d : swept_)
        if (d.r >= 0) in_run_.push_back(d), reach = std::max(reach, 2 * d.r);
    if (in_run_.size() < 2) return;
    grid_.build(in_run_.data(), in_run_.size(), reach);
    constexpr int kColumns = 16;  // grid columns per task
    pool.for_each(std::size_t((grid_.columns() + kColumns - 1) / kColumns), [&](std::size_t task, int worker) {
        const int from = int(task) * kColumns;
        grid_.overlaps(from, std::min(grid_.columns(), from + kColumns),
                       [&](int a, int b) { test_pair(a, b, first, frames, pairs_[std::size_t(worker)]); });
    });
}

// Agents a and b at frames [first, first + frames) of the group where both are in the run: FrameGrid's
// test, |p_a - p_b| < r_a + r_b, on the same numbers.
void FrameStream::test_pair(int a, int b, std::int64_t first, std::int64_t frames, std::vector<Contact>& out) const {
    const std::size_t n = tracks_.size();
    const std::array<double, 4>* p = &disks_[std::size_t(first) * n + std::size_t(a)];
    const std::array<double, 4>* q = &disks_[std::size_t(first) * n + std::size_t(b)];
    for (std::int64_t k = 0; k < frames; ++k) {
        const std::array<double, 4>&pa = p[std::size_t(k) * n], &qb = q[std::size_t(k) * n];
        const double dx = pa[1] - qb[1], dy = pa[2] - qb[2], r = pa[3] + qb[3];
        if (dx * dx + dy * dy < r * r) out.push_back({next_ + first + k, std::min(a, b), std::max(a, b), false});
    }
}

// A frame's contacts counted (excused where a fallback clip plays) and its metrics, in frame order.
void FrameStream::count_contacts(std::int64_t frame, const std::array<double, 4>* disks, const char* fallback,
                                 std::vector<Contact>& found) {
    for (Contact& c : found) {
        c.excused = fallback[c.a] || fallback[c.b];
        ++contacts_;
        excused_ += c.excused;
    }
    metrics_.contacts(frame, disks, found.data(), found.size());
}

}  // namespace mobb::crowd
