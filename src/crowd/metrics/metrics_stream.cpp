#include "metrics/metrics_stream.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "metrics/agent_sums.h"
#include "world/planar.h"

namespace mobb::crowd {

namespace {

constexpr double kSteerFrame = 0.05;  // s: SteerSuite's 20 frames per second (metrics.cpp's `effort`)

}  // namespace

MetricsStream::MetricsStream(const Record& header, const MotionGraph& graph, double goal_radius)
    : header_(header),
      radius_(goal_radius),
      half_(std::llround(0.5 * CrowdMetrics::kIdleWindow / header.dt)),
      solids_(header.world.solids()),
      tracks_(header.tracks.size()),
      ring_size_(std::size_t(2 * half_ + 3)),  // the idle window and a resampling step behind the last frame
      ring_(tracks_.size() * ring_size_) {
    m_.graph_speed = graph_mean_speed(graph);
    m_.walking_speed = graph_walking_speed(graph);
    boxes_.reserve(solids_.size());
    for (const Polygon& p : solids_) boxes_.push_back(bounds(p));
}

void MetricsStream::contacts(std::int64_t f, const std::array<double, 4>* disks, const Contact* contacts,
                             std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
        const Contact& c = contacts[k];
        const auto& p = disks[std::size_t(c.a)];
        const auto& q = disks[std::size_t(c.b)];
        const double depth = p[3] + q[3] - planar_distance(p[1] - q[1], p[2] - q[2]);
        ++m_.contacts;
        if (!c.excused) ++m_.contacts_outside_fallbacks;
        m_.max_penetration = std::max(m_.max_penetration, depth);
        if (depth <= 1e-3) continue;  // SteerSuite's 1 mm
        const auto it = last_contact_.find({c.a, c.b});
        if (it == last_contact_.end() || it->second + 1 < f)
            ++tracks_[std::size_t(c.a)].collisions, ++tracks_[std::size_t(c.b)].collisions;
        last_contact_[{c.a, c.b}] = f;
    }
    for (auto it = last_contact_.begin(); it != last_contact_.end();)
        it = it->second < f ? last_contact_.erase(it) : std::next(it);
}

void MetricsStream::frames(std::int64_t first, std::int64_t count, const std::array<double, 4>* disks,
                           const std::array<double, 2>* roots, util::WorkerPool& pool) {
    constexpr std::size_t kAgents = 512;  // agents per task: enough work to share, little to wait for at the end
    const std::size_t n = tracks_.size();
    std::vector<Counts> counts(std::size_t(pool.size()));
    pool.for_each((n + kAgents - 1) / kAgents, [&](std::size_t task, int worker) {
        for (std::size_t a = task * kAgents; a < std::min(n, (task + 1) * kAgents); ++a)
            for (std::int64_t k = 0; k < count && !tracks_[a].ended; ++k) {
                const std::size_t at = std::size_t(k) * n + a;
                const std::array<double, 4>& disk = disks[at];
                if (std::isnan(disk[0])) {
                    tracks_[a].left = true;
                    end(a, counts[std::size_t(worker)]);
                } else {
                    const std::array<double, 2> root = roots ? roots[at] : std::array<double, 2>{disk[1], disk[2]};
                    sample(a, first + k, disk, root, counts[std::size_t(worker)]);
                }
            }
    });
    for (const Counts& c : counts) add(c);
}

void MetricsStream::add(const Counts& counts) {
    m_.samples_outside += counts.samples_outside;
    m_.obstacle_contacts += counts.obstacle_contacts;
    idle_ += counts.idle;
}

void MetricsStream::sample(std::size_t a, std::int64_t f, const std::array<double, 4>& s,
                           const std::array<double, 2>& root, Counts& counts) {
    Track& t = tracks_[a];
    const double x = s[1], y = s[2];
    if (t.n == 0) t.start = root;
    // Within the radius of each goal in turn (metrics.cpp's `arrival`): a frame may reach several.
    const auto& goals = header_.tracks[a].goals;
    while (t.reached < 0 && t.goal < goals.size() &&
           planar_distance(x - goals[t.goal][0], y - goals[t.goal][1]) < radius_) {
        if (t.goal + 1 == goals.size())
            t.reached = f;
        else
            ++t.goal;
    }
    if (t.n > 0) {
        const auto& p = at(a, f - 1);
        const double step = planar_distance(root[0] - p[0], root[1] - p[1]);
        t.length += step;
        if (t.reached < 0 || f - 1 < t.reached) t.to_goal += step;
    }
    if (!header_.world.inside(x, y)) ++counts.samples_outside;
    ring_[a * ring_size_ + std::size_t(f) % ring_size_] = root;
    t.n = f + 1;
    solid(a, f, s, counts);
    idle(a, t, counts);
    effort(a, t);
}

void MetricsStream::solid(std::size_t a, std::int64_t f, const std::array<double, 4>& s, Counts& counts) {
    for (std::size_t k = 0; k < solids_.size(); ++k) {
        const auto& b = boxes_[k];
        if (s[1] + s[3] < b[0] || s[1] - s[3] > b[2] || s[2] + s[3] < b[1] || s[2] - s[3] > b[3]) continue;
        if (!disk_overlaps(solids_[k], s[1], s[2], s[3])) continue;
        Track& t = tracks_[a];
        ++counts.obstacle_contacts;
        if (t.last_solid + 1 < f) ++t.collisions;
        t.last_solid = f;
        return;
    }
}

// The frames whose idle window has its last frame in (metrics.cpp's `idle_frames`); at the track's end,
// the rest, their windows cut there.
void MetricsStream::idle(std::size_t a, Track& t, Counts& counts) {
    const double dt = header_.dt;
    while (!t.idle_done) {
        const std::int64_t f = t.idle_next;
        const std::int64_t until =
            t.reached >= 0 ? t.reached : (t.ended ? t.n : std::numeric_limits<std::int64_t>::max());
        if (f >= until) {
            t.idle_done = true;
            break;
        }
        if (!t.ended && f + half_ > t.n - 1) break;  // its window is not all there yet
        const std::int64_t lo = std::max<std::int64_t>(0, f - half_), hi = std::min(t.n - 1, f + half_);
        const auto &p = at(a, lo), &q = at(a, hi);
        const double d = planar_distance(q[0] - p[0], q[1] - p[1]);
        if (hi > lo && d / (double(hi - lo) * dt) < CrowdMetrics::kIdleSpeed) {
            ++counts.idle;
            t.longest = std::max(t.longest, ++t.run);
        } else {
            t.run = 0;
        }
        ++t.idle_next;
    }
}

// Position at `time`, linear between frames, held at the ends (metrics.cpp's `at_time`): before the
// track's end only where the two frames are in.
std::array<double, 2> MetricsStream::at_time(std::size_t a, const Track& t, double time) const {
    const double f = std::clamp(time / header_.dt, 0.0, double(t.n - 1));
    const auto i = std::int64_t(f);
    const std::int64_t j = std::min(i + 1, t.n - 1);
    const double u = f - double(i);
    const auto &p = at(a, i), &q = at(a, j);
    return {p[0] + (q[0] - p[0]) * u, p[1] + (q[1] - p[1]) * u};
}

// SteerSuite's energy and acceleration sums (metrics.cpp's `effort`), a 20 Hz step once both its ends are
// in and it is sure to count: up to the arrival, or the run's end.
void MetricsStream::effort(std::size_t a, Track& t) {
    const double dt = header_.dt;
    while (!t.effort_done) {
        const int k = t.effort_next;
        const double next = double(k + 1) * kSteerFrame;
        if (t.reached >= 0 || t.ended) {
            const double end = t.reached >= 0 ? double(t.reached) * dt : double(header_.frames) * dt;
            if (!(next <= end + 1e-9)) {
                t.effort_done = true;
                break;
            }
        } else if (!(next <= double(t.n) * dt + 1e-9)) {
            break;  // it may count: the arrival, if any, is later
        }
        if (!t.ended && !(next / dt < double(t.n - 1))) break;  // the frame after it is not in yet
        const auto p = at_time(a, t, k * kSteerFrame), q = at_time(a, t, (k + 1) * kSteerFrame);
        const double vx = (q[0] - p[0]) / kSteerFrame, vy = (q[1] - p[1]) / kSteerFrame;
        t.energy += 0.5 * (vx * vx + vy * vy);
        if (k > 0) t.acceleration += planar_distance(vx - t.vx0, vy - t.vy0) / kSteerFrame;
        t.vx0 = vx, t.vy0 = vy;
        ++t.effort_next;
    }
}

void MetricsStream::end(std::size_t a, Counts& counts) {
    Track& t = tracks_[a];
    t.ended = true;
    if (t.n == 0) return;
    idle(a, t, counts);
    effort(a, t);
}

CrowdMetrics MetricsStream::finish(std::uint64_t choice_points, std::uint64_t fallbacks) {
    Counts counts;
    for (std::size_t a = 0; a < tracks_.size(); ++a)
        if (!tracks_[a].ended) end(a, counts);
    add(counts);
    CrowdMetrics m = m_;
    m.choice_points = choice_points;
    m.fallbacks = fallbacks;
    m.fallback_share = m.choice_points ? double(m.fallbacks) / double(m.choice_points) : 0.0;
    const double dt = header_.dt, run = double(header_.frames) * dt;
    AgentSums sums;
    for (std::size_t a = 0; a < tracks_.size(); ++a) {
        const Track& t = tracks_[a];
        const auto& goals = header_.tracks[a].goals;
        AgentOutcome o;
        o.speed = t.n > 1 ? t.length / (double(t.n - 1) * dt) : 0.0;
        o.reached = t.reached;
        o.counted = t.reached >= 0 ? t.reached : t.n;
        o.longest_idle = double(t.longest) * dt;
        o.has_goals = !goals.empty();
        o.left = t.left;
        o.to_goal = t.to_goal;
        if (t.reached >= 0) {
            double x = t.start[0], y = t.start[1];
            for (const auto& g : goals) {
                o.straight += planar_distance(g[0] - x, g[1] - y);
                x = g[0], y = g[1];
            }
        }
        o.enabled = t.reached >= 0 ? double(t.reached) * dt : run;
        o.collisions = t.collisions;
        o.energy = t.energy;
        o.acceleration = t.acceleration;
        sums.add(o, dt, m);
    }
    sums.finish(tracks_.size(), idle_, m);
    return m;
}

}  // namespace mobb::crowd
