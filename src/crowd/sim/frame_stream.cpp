#include "sim/frame_stream.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mobb/core/assert.h"

namespace mobb::crowd {

namespace {

using Clock = std::chrono::steady_clock;

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
    // Frames are checked in parallel, each by one worker; the contacts are counted and measured in frame
    // order, so the outcome is the same for any number of threads.
    scratch_.resize(std::size_t(pool.size()));
    found_.resize(std::size_t(count));
    pool.for_each(std::size_t(count), [&](std::size_t k, int worker) {
        find_contacts(next_ + std::int64_t(k), &disks_[k * n], scratch_[std::size_t(worker)], found_[k]);
    });
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

// The frame-by-frame contact check of one frame (as frame_contacts does it on a whole record): its
// contacts, by agent pair.
void FrameStream::find_contacts(std::int64_t frame, const std::array<double, 4>* disks, CheckScratch& scratch,
                                std::vector<Contact>& out) {
    std::vector<FrameGrid::Disk>& in_run = scratch.in_run;
    in_run.clear();
    out.clear();
    double rmax = 0;  // contacts are closer than 2 rmax
    for (std::size_t a = 0; a < tracks_.size(); ++a) {
        if (std::isnan(disks[a][0])) continue;
        in_run.push_back({disks[a][1], disks[a][2], disks[a][3], int(a)});
        rmax = std::max(rmax, disks[a][3]);
    }
    if (in_run.size() < 2) return;
    scratch.grid.build(in_run.data(), in_run.size(), 2 * rmax);
    scratch.grid.overlaps([&](int a, int b) { out.push_back({frame, std::min(a, b), std::max(a, b), false}); });
    std::sort(out.begin(), out.end(),
              [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
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
