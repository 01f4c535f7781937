#include "mobb/crowd/metrics/metrics.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

#include <nlohmann/json.hpp>

#include "metrics/agent_sums.h"
#include "mobb/core/assert.h"
#include "mobb/util/json_text.h"
#include "world/planar.h"

namespace mobb::crowd {

namespace {

using Samples = std::vector<std::array<double, 4>>;

double step(const Samples& s, std::size_t f) { return planar_distance(s[f + 1][1] - s[f][1], s[f + 1][2] - s[f][2]); }

// Where the agent's root is at each of its frames, [t, x, y, r] as its samples: placed from its clips as
// the samples are (the core's transform), for a graph whose disks are centred on the body.
Samples roots_of(const AgentTrack& t, const MotionGraph& g) {
    Samples out;
    out.reserve(t.samples.size());
    std::size_t k = 0;
    Rigid2 m = Rigid2::of(t.clips.at(0).place);
    for (std::size_t f = 0; f < t.samples.size(); ++f) {
        if (k + 1 < t.clips.size() && t.clips[k + 1].start <= std::int64_t(f)) m = Rigid2::of(t.clips[++k].place);
        const PlacedClip& c = t.clips[k];
        const GraphClip& clip = g.clips.at(std::size_t(c.clip));
        const auto i = std::size_t(std::int64_t(f) - c.start);
        MOBB_ASSERT(i < clip.path.size());
        const glm::dvec2 p = placed_root(clip, m, i);
        out.push_back({t.samples[f][0], p.x, p.y, t.samples[f][3]});
    }
    return out;
}

// The first frame within `radius` of the last goal after coming within it of each goal before in turn,
// or -1.
std::int64_t arrival(const AgentTrack& t, double radius) {
    std::size_t f = 0;
    for (std::size_t k = 0; k < t.goals.size(); ++k) {
        const auto& g = t.goals[k];
        while (f < t.samples.size() && !(planar_distance(t.samples[f][1] - g[0], t.samples[f][2] - g[1]) < radius)) ++f;
        if (f == t.samples.size()) return -1;
        if (k + 1 == t.goals.size()) return std::int64_t(f);
    }
    return -1;
}

// The straight lines from the start through the goals in turn, metres.
double straight_length(const AgentTrack& t, const Samples& root) {
    double length = 0, x = root[0][1], y = root[0][2];
    for (const auto& g : t.goals) {
        length += planar_distance(g[0] - x, g[1] - y);
        x = g[0], y = g[1];
    }
    return length;
}

// Idle frames of one agent before `until`: ground speed over the window centred on the frame below the
// idle speed. Adds them to `idle` and returns the longest stretch in frames.
std::int64_t idle_frames(const Samples& s, std::int64_t until, double dt, std::uint64_t& idle) {
    const auto half = std::int64_t(std::llround(0.5 * CrowdMetrics::kIdleWindow / dt));
    const auto n = std::int64_t(s.size());
    std::int64_t run = 0, longest = 0;
    for (std::int64_t f = 0; f < until; ++f) {
        const std::int64_t a = std::max<std::int64_t>(0, f - half), b = std::min(n - 1, f + half);
        const double d =
            planar_distance(s[std::size_t(b)][1] - s[std::size_t(a)][1], s[std::size_t(b)][2] - s[std::size_t(a)][2]);
        if (b > a && d / (double(b - a) * dt) < CrowdMetrics::kIdleSpeed) {
            ++idle;
            longest = std::max(longest, ++run);
        } else {
            run = 0;
        }
    }
    return longest;
}

// Position at time t, linear between frames (dt apart), held at the ends.
std::array<double, 2> at_time(const Samples& s, double t, double dt) {
    const double f = std::clamp(t / dt, 0.0, double(s.size() - 1));
    const auto i = std::size_t(f);
    const std::size_t j = std::min(i + 1, s.size() - 1);
    const double u = f - double(i);
    return {s[i][1] + (s[j][1] - s[i][1]) * u, s[i][2] + (s[j][2] - s[i][2]) * u};
}

// SteerSuite's per-agent energy and acceleration sums at its 20 frames per second, up to time `end`.
std::pair<double, double> effort(const Samples& s, double dt, double end) {
    constexpr double kFrame = 0.05;
    double energy = 0, acceleration = 0, vx0 = 0, vy0 = 0;
    for (int k = 0; double(k + 1) * kFrame <= end + 1e-9; ++k) {
        const auto p = at_time(s, k * kFrame, dt), q = at_time(s, (k + 1) * kFrame, dt);
        const double vx = (q[0] - p[0]) / kFrame, vy = (q[1] - p[1]) / kFrame;
        energy += 0.5 * (vx * vx + vy * vy);
        if (k > 0) acceleration += planar_distance(vx - vx0, vy - vy0) / kFrame;
        vx0 = vx, vy0 = vy;
    }
    return {energy, acceleration};
}

// Collision episodes per agent (a contact with the same other agent or solid over consecutive frames
// counts once, for each of the two agents), deeper than SteerSuite's 1 mm.
std::vector<int> episodes(const Record& r, const std::vector<Contact>& contacts,
                          const std::vector<std::vector<std::int64_t>>& solid_frames) {
    std::vector<int> out(r.tracks.size(), 0);
    std::map<std::pair<int, int>, std::int64_t> last;  // pair -> last frame in contact
    for (const Contact& c : contacts) {
        const auto& p = r.tracks[std::size_t(c.a)].samples[std::size_t(c.frame)];
        const auto& q = r.tracks[std::size_t(c.b)].samples[std::size_t(c.frame)];
        if (p[3] + q[3] - planar_distance(p[1] - q[1], p[2] - q[2]) <= 1e-3) continue;
        auto it = last.find({c.a, c.b});
        if (it == last.end() || it->second + 1 < c.frame) ++out[std::size_t(c.a)], ++out[std::size_t(c.b)];
        last[{c.a, c.b}] = c.frame;
    }
    for (std::size_t a = 0; a < solid_frames.size(); ++a)
        for (std::size_t k = 0; k < solid_frames[a].size(); ++k)
            if (k == 0 || solid_frames[a][k - 1] + 1 < solid_frames[a][k]) ++out[a];
    return out;
}

// Frames at which each agent's disk overlaps a wall or an obstacle.
std::vector<std::vector<std::int64_t>> solid_contacts(const Record& r) {
    const std::vector<Polygon> solids = r.world.solids();
    std::vector<std::array<double, 4>> boxes;
    boxes.reserve(solids.size());
    for (const Polygon& p : solids) boxes.push_back(bounds(p));
    std::vector<std::vector<std::int64_t>> out(r.tracks.size());
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (std::size_t f = 0; f < r.tracks[a].samples.size(); ++f) {
            const auto& s = r.tracks[a].samples[f];
            for (std::size_t k = 0; k < solids.size(); ++k) {
                const auto& b = boxes[k];
                if (s[1] + s[3] < b[0] || s[1] - s[3] > b[2] || s[2] + s[3] < b[1] || s[2] - s[3] > b[3]) continue;
                if (disk_overlaps(solids[k], s[1], s[2], s[3])) {
                    out[a].push_back(std::int64_t(f));
                    break;
                }
            }
        }
    return out;
}

void contact_metrics(const Record& r, CrowdMetrics& m, std::vector<int>& collisions) {
    const std::vector<Contact> contacts = frame_contacts(r);
    for (const Contact& c : contacts) {
        ++m.contacts;
        if (!c.excused) ++m.contacts_outside_fallbacks;
        const auto& p = r.tracks[std::size_t(c.a)].samples[std::size_t(c.frame)];
        const auto& q = r.tracks[std::size_t(c.b)].samples[std::size_t(c.frame)];
        m.max_penetration = std::max(m.max_penetration, p[3] + q[3] - planar_distance(p[1] - q[1], p[2] - q[2]));
    }
    const auto solid = solid_contacts(r);
    for (const auto& frames : solid) m.obstacle_contacts += frames.size();
    collisions = episodes(r, contacts, solid);
}

}  // namespace

namespace {

// Root path length over duration (m/s).
double clip_speed(const GraphClip& c) {
    double length = 0;
    for (std::size_t i = 0; i + 1 < c.path.size(); ++i) {
        const glm::dvec2 p = root_at(c, i), q = root_at(c, i + 1);
        length += planar_distance(q.x - p.x, q.y - p.y);
    }
    return length / c.path.duration();
}

}  // namespace

double graph_mean_speed(const MotionGraph& graph) {
    double sum = 0;
    for (const GraphClip& c : graph.clips) sum += clip_speed(c);
    return graph.clips.empty() ? 0.0 : sum / double(graph.clips.size());
}

double graph_walking_speed(const MotionGraph& graph) {
    double sum = 0;
    int walks = 0;
    for (int k = 0; k < int(graph.clips.size()); ++k) {
        if (kind_of(graph.clips[std::size_t(k)], k) != ClipKind::Walk) continue;
        sum += clip_speed(graph.clips[std::size_t(k)]);
        ++walks;
    }
    return walks ? sum / walks : 0.0;
}

CrowdMetrics crowd_metrics(const Record& r, const MotionGraph& graph, double goal_radius) {
    CrowdMetrics m;
    m.choice_points = r.choices.size();
    for (const ChoicePoint& c : r.choices) m.fallbacks += c.fallback;
    m.fallback_share = m.choice_points ? double(m.fallbacks) / double(m.choice_points) : 0.0;
    std::vector<int> collisions;
    contact_metrics(r, m, collisions);
    m.graph_speed = graph_mean_speed(graph);
    m.walking_speed = graph_walking_speed(graph);
    const double dt = r.dt, run = double(r.frames) * dt;
    std::uint64_t idle = 0;
    AgentSums sums;
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        const AgentTrack& t = r.tracks[a];
        const Samples& s = t.samples;
        // How the agent moves is its root's; its disk is where it stands (contacts, goals, the world).
        const Samples body_roots = graph.centre == io::PathCentre::Root || s.empty() ? Samples() : roots_of(t, graph);
        const Samples& root = body_roots.empty() ? s : body_roots;
        double length = 0;
        for (std::size_t f = 0; f + 1 < s.size(); ++f) {
            length += step(root, f);
            if (!r.world.inside(s[f][1], s[f][2])) ++m.samples_outside;
        }
        if (!s.empty() && !r.world.inside(s.back()[1], s.back()[2])) ++m.samples_outside;
        AgentOutcome o;
        o.speed = s.size() > 1 ? length / (double(s.size() - 1) * dt) : 0.0;
        o.reached = arrival(t, goal_radius);
        o.counted = o.reached >= 0 ? o.reached : std::int64_t(s.size());
        o.longest_idle = double(idle_frames(root, o.counted, dt, idle)) * dt;
        for (std::int64_t f = 0; f < o.counted && std::size_t(f) + 1 < s.size(); ++f)
            o.to_goal += step(root, std::size_t(f));
        o.has_goals = !t.goals.empty();
        o.left = t.left_frame.has_value();
        if (o.reached >= 0) o.straight = straight_length(t, root);
        o.enabled = o.reached >= 0 ? double(o.reached) * dt : run;
        std::tie(o.energy, o.acceleration) = effort(root, dt, o.enabled);
        o.collisions = collisions[a];
        sums.add(o, dt, m);
    }
    sums.finish(r.tracks.size(), idle, m);
    return m;
}

std::string metrics_json(const CrowdMetrics& m) {
    using util::rounded;
    nlohmann::ordered_json j;
    j["choice_points"] = m.choice_points;
    j["fallbacks"] = m.fallbacks;
    j["fallback_share"] = rounded(m.fallback_share, 6);
    j["contacts"] = m.contacts;
    j["contacts_outside_fallbacks"] = m.contacts_outside_fallbacks;
    j["max_penetration"] = rounded(m.max_penetration, 6);
    j["samples_outside"] = m.samples_outside;
    j["obstacle_contacts"] = m.obstacle_contacts;
    j["mean_speed"] = rounded(m.mean_speed, 6);
    j["graph_speed"] = rounded(m.graph_speed, 6);
    j["speed_ratio"] = rounded(m.speed_ratio, 6);
    j["idle_share"] = rounded(m.idle_share, 6);
    j["longest_idle"] = rounded(m.longest_idle, 6);
    j["goal_agents"] = m.goal_agents;
    j["reached"] = m.reached;
    j["left"] = m.left;
    j["mean_time_to_goal"] = rounded(m.mean_time_to_goal, 6);
    j["max_time_to_goal"] = rounded(m.max_time_to_goal, 6);
    j["path_ratio"] = rounded(m.path_ratio, 6);
    j["walking_speed"] = rounded(m.walking_speed, 6);
    j["time_ratio"] = rounded(m.time_ratio, 6);
    j["passed"] = m.passed;
    j["composite01"] = rounded(m.composite01, 4);
    j["composite02"] = rounded(m.composite02, 4);
    return j.dump();
}

std::string metrics_text(const CrowdMetrics& m) {
    std::ostringstream out;
    out << "fallback share           " << 100.0 * m.fallback_share << " % of choice points\n"
        << "contacts                 " << m.contacts << " agent-pair frames (deepest " << m.max_penetration << " m), "
        << m.obstacle_contacts << " agent frames on walls or obstacles, " << m.samples_outside
        << " samples outside the world\n"
        << "speed                    " << m.mean_speed << " m/s, " << m.speed_ratio
        << " of the graph's mean clip speed (" << m.graph_speed << " m/s)\n"
        << "idle                     " << 100.0 * m.idle_share << " % of agent time, longest " << m.longest_idle
        << " s\n";
    if (m.goal_agents > 0)
        out << "goals                    " << m.reached << " of " << m.goal_agents << " reached (" << m.left
            << " left the run there), mean " << m.mean_time_to_goal << " s, last " << m.max_time_to_goal << " s, path "
            << m.path_ratio << " x the straight line: " << (m.passed ? "PASSED" : "FAILED") << "\n"
            << "time to goal             " << m.time_ratio << " x the straight line at the graph's walking speed ("
            << m.walking_speed << " m/s)\n";
    out << "SteerSuite composite     01: " << m.composite01 << ", 02: " << m.composite02 << " (lower is better)\n";
    return out.str();
}

}  // namespace mobb::crowd
