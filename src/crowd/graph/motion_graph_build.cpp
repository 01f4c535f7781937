// Building a motion graph from mocap (Kovar et al. 2002, hub poses after Snap-Together Motion): all
// pairs of poses, transition points, cuts into clips, the largest strongly connected part.
#include "mobb/crowd/graph/motion_graph.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <ostream>

#include "mobb/core/angle.h"
#include "mobb/crowd/graph/pose_distance.h"
#include "mobb/io/load.h"
#include "mobb/util/json_text.h"

namespace mobb::crowd {

namespace {

// Loads at the graph's rate, dropping a stray first frame far from the rest (CMU 007_03..007_12).
// "FILE:A:B": frames [A, B) of FILE; anything else: the whole file.
void parse_input(const std::string& input, GraphSource& src, std::string& file) {
    file = input;
    const auto b = input.rfind(':');
    if (b == std::string::npos || b == 0) return;
    const auto a = input.rfind(':', b - 1);
    if (a == std::string::npos) return;
    const std::string first = input.substr(a + 1, b - a - 1), end = input.substr(b + 1);
    const auto digits = [](const std::string& t) {
        return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (!digits(first) || !digits(end)) return;
    file = input.substr(0, a);
    src.frame_begin = std::stoi(first);
    src.frame_end = std::stoi(end);
    if (src.frame_end <= src.frame_begin) throw GraphError(input + ": expected frames A:B with A < B");
}

// A source at the graph's rate: its range, or the whole file without a stray first frame.
io::Clip load_source(const std::string& file, const GraphBuildOptions& o, GraphSource& src) {
    io::LoadOptions lo;
    lo.fps = o.fps;
    lo.frame_begin = src.frame_begin;
    lo.frame_end = src.frame_end;
    io::Clip clip = io::load_clip(file, lo);
    const auto& s = clip.path.samples;
    if (src.frame_end < 0 && s.size() > 2 && std::hypot(s[1].x - s[0].x, s[1].y - s[0].y) > o.trim_jump) {
        src.frame_begin = 1;
        lo.frame_begin = 1;
        clip = io::load_clip(file, lo);
    }
    return clip;
}

// An idle clip (ClipKind::Idle, before its snap) loops in place: its exit becomes the identity.
void snap_idle(GraphClip& c, int id) {
    const bool loops = std::find(c.successors.begin(), c.successors.end(), id) != c.successors.end();
    if (!loops || root_reach_of(c) > kIdleReach || std::hypot(c.exit_x, c.exit_y) > kIdleExit ||
        std::abs(c.exit_heading) > kIdleTurn)
        return;
    c.idle_drift = util::rounded(std::hypot(c.exit_x, c.exit_y));
    c.idle_turn = util::rounded(c.exit_heading, 9);
    c.exit_x = c.exit_y = c.exit_heading = 0;
}

// All frames of all sources in one distance matrix (floats, metres), sources one after another.
struct AllPairs {
    std::vector<int> offset;  // first global frame of each source, plus the total at the end
    std::vector<float> d;     // [g1 * total + g2]

    int total() const { return offset.back(); }
    float at(int g1, int g2) const { return d[std::size_t(g1) * std::size_t(total()) + std::size_t(g2)]; }
};

AllPairs all_pairs(const std::vector<PoseTrack>& tracks, int window) {
    AllPairs m;
    m.offset.push_back(0);
    for (const PoseTrack& t : tracks) m.offset.push_back(m.offset.back() + t.frames);
    const std::size_t n = std::size_t(m.total());
    m.d.assign(n * n, 0.0f);
    for (std::size_t a = 0; a < tracks.size(); ++a)
        for (std::size_t b = a; b < tracks.size(); ++b) {
            const std::vector<float> block = distance_matrix(tracks[a], tracks[b], window);
            const int na = tracks[a].frames, nb = tracks[b].frames;
            for (int i = 0; i < na; ++i)
                for (int j = 0; j < nb; ++j) {
                    const std::size_t gi = std::size_t(m.offset[a]) + std::size_t(i);
                    const std::size_t gj = std::size_t(m.offset[b]) + std::size_t(j);
                    m.d[gi * n + gj] = m.d[gj * n + gi] = block[std::size_t(i) * std::size_t(nb) + std::size_t(j)];
                }
        }
    return m;
}

// Transition points of a hub pose: in every source, the frames where the distance to the hub is a
// local minimum (along the source) under the threshold.
std::vector<int> hub_matches(const AllPairs& m, int hub, double threshold) {
    std::vector<int> out;
    for (std::size_t s = 0; s + 1 < m.offset.size(); ++s)
        for (int g = m.offset[s]; g < m.offset[s + 1]; ++g) {
            const float v = m.at(hub, g);
            if (double(v) >= threshold) continue;
            const bool left = g == m.offset[s] || m.at(hub, g - 1) >= v;
            const bool right = g + 1 == m.offset[s + 1] || m.at(hub, g + 1) > v;
            if (left && right) out.push_back(g);
        }
    return out;
}

// Hub poses in the spirit of Snap-Together Motion: greedily, the pose whose transition points add
// the most new cut candidates (frames farther than 0.3 s from the candidates already chosen).
std::vector<bool> hub_candidates(const AllPairs& m, int hubs, const GraphBuildOptions& o, int& transitions) {
    std::vector<bool> cand(std::size_t(m.total()), false);
    std::vector<bool> near(std::size_t(m.total()), false);
    const int spread = int(std::lround(0.3 * o.fps));
    transitions = 0;
    for (int k = 0; k < hubs; ++k) {
        int best = -1, best_score = 0;
        for (int h = 0; h < m.total(); ++h) {
            int score = 0;
            for (int g : hub_matches(m, h, o.threshold)) score += near[std::size_t(g)] ? 0 : 1;
            if (score > best_score) {
                best_score = score;
                best = h;
            }
        }
        if (best < 0) break;
        for (int g : hub_matches(m, best, o.threshold)) {
            ++transitions;
            cand[std::size_t(g)] = true;
            for (int f = g - spread; f <= g + spread; ++f)
                if (f >= 0 && f < m.total()) near[std::size_t(f)] = true;
        }
    }
    return cand;
}

// Cuts one source into clips of min..max samples near the target length, cutting at transition
// points where it can (elsewhere a clip joins only its own continuation). The first clip starts at
// frame 0 or at a transition point, the last ends at the last frame or at one: frames dropped at
// either end cost a little, so the cut favours clips that start and end at hub poses.
std::vector<int> choose_cuts(int n, const std::vector<bool>& candidate, const GraphBuildOptions& o) {
    const int lo = int(std::lround(o.min_clip * o.fps)), hi = int(std::lround(o.max_clip * o.fps));
    const double target = o.target_clip * o.fps;
    const double drop = 0.2 / o.fps;  // per dropped frame
    const int last = n - 1;
    if (last < lo) return {};
    const double inf = std::numeric_limits<double>::infinity();
    auto is_cand = [&](int p) { return candidate[std::size_t(p)]; };
    std::vector<double> best(std::size_t(n), inf);
    std::vector<int> from(std::size_t(n), -1);
    for (int p = 0; p < n; ++p)
        if (p == 0 || is_cand(p)) best[std::size_t(p)] = drop * p;
    for (int p = lo; p <= last; ++p) {
        const double cut_cost = (p == last || is_cand(p)) ? 0.0 : 2.0;
        for (int q = std::max(0, p - hi); q <= p - lo; ++q) {
            if (best[std::size_t(q)] == inf) continue;
            const double len = (double(p - q) - target) / target;
            const double c = best[std::size_t(q)] + len * len + cut_cost;
            if (c < best[std::size_t(p)]) {
                best[std::size_t(p)] = c;
                from[std::size_t(p)] = q;
            }
        }
    }
    int end = -1;
    double end_cost = inf;
    for (int p = lo; p <= last; ++p) {
        if (p != last && !is_cand(p)) continue;
        if (from[std::size_t(p)] < 0) continue;
        const double c = best[std::size_t(p)] + drop * (last - p);
        if (c < end_cost) {
            end_cost = c;
            end = p;
        }
    }
    std::vector<int> cuts;
    for (int p = end; p >= 0; p = from[std::size_t(p)]) cuts.push_back(p);
    std::reverse(cuts.begin(), cuts.end());
    return cuts;
}

// Tarjan's strongly connected components; returns the component index of every node.
std::vector<int> components(const std::vector<std::vector<int>>& succ, int& count) {
    const int n = int(succ.size());
    std::vector<int> index(std::size_t(n), -1), low(std::size_t(n), 0), comp(std::size_t(n), -1), stack;
    std::vector<bool> on(std::size_t(n), false);
    int next = 0;
    count = 0;
    std::function<void(int)> visit = [&](int v) {
        index[std::size_t(v)] = low[std::size_t(v)] = next++;
        stack.push_back(v);
        on[std::size_t(v)] = true;
        for (int w : succ[std::size_t(v)]) {
            if (index[std::size_t(w)] < 0) {
                visit(w);
                low[std::size_t(v)] = std::min(low[std::size_t(v)], low[std::size_t(w)]);
            } else if (on[std::size_t(w)]) {
                low[std::size_t(v)] = std::min(low[std::size_t(v)], index[std::size_t(w)]);
            }
        }
        if (low[std::size_t(v)] != index[std::size_t(v)]) return;
        for (int w = -1; w != v;) {
            w = stack.back();
            stack.pop_back();
            on[std::size_t(w)] = false;
            comp[std::size_t(w)] = count;
        }
        ++count;
    };
    for (int v = 0; v < n; ++v)
        if (index[std::size_t(v)] < 0) visit(v);
    return comp;
}

// The clip's path in its own frame (its disks from `disks`, the source's path centred as the graph asks),
// its root there when the disks are not centred on it, and the exit transform.
void localise(GraphClip& c, const io::Clip& clip, const Path& disks, io::PathCentre centre, const PoseTrack& track) {
    const glm::dvec2 o = track.root[std::size_t(c.first)];
    const double h = track.heading[std::size_t(c.first)];
    const double cs = std::cos(h), sn = std::sin(h);
    auto local = [&](double x, double y, double& lx, double& ly) {
        const double dx = x - o.x, dy = y - o.y;
        lx = util::rounded(cs * dx + sn * dy);
        ly = util::rounded(-sn * dx + cs * dy);
    };
    c.path.dt = clip.path.dt;
    c.path.samples.clear();
    c.root.clear();
    for (int i = c.first; i < c.exit; ++i) {
        const Sample& s = disks.samples[std::size_t(i)];
        Sample l;
        local(s.x, s.y, l.x, l.y);
        l.r = util::rounded(s.r);
        c.path.samples.push_back(l);
        if (centre == io::PathCentre::Root) continue;
        const Sample& root = clip.path.samples[std::size_t(i)];
        glm::dvec2& r = c.root.emplace_back();
        local(root.x, root.y, r.x, r.y);
    }
    const Sample& e = clip.path.samples[std::size_t(c.exit)];
    local(e.x, e.y, c.exit_x, c.exit_y);
    c.exit_heading = util::rounded(wrap_angle(track.heading[std::size_t(c.exit)] - h), 9);
}

}  // namespace

MotionGraph build_motion_graph(const std::vector<std::string>& files, const GraphBuildOptions& o, std::ostream* log) {
    if (files.empty()) throw GraphError("graph build: no input files");
    if (!(o.fps >= kMinGraphFps && o.fps <= kMaxGraphFps) || !(o.threshold > 0) || o.window < 1 || !(o.min_clip > 0) ||
        o.max_clip < o.min_clip)
        throw GraphError("graph build: invalid options");
    MotionGraph g;
    g.fps = o.fps;
    g.threshold = o.threshold;
    g.window = o.window;
    g.centre = o.centre;
    std::vector<io::Clip> clips;
    std::vector<PoseTrack> tracks;
    for (const std::string& input : files) {
        GraphSource src;
        std::string f;
        parse_input(input, src, f);
        clips.push_back(load_source(f, o, src));
        const PoseJoints joints = select_joints(clips.back().animation.skeleton);
        if (g.joints.empty()) g.joints = joints.names;
        tracks.push_back(pose_track(clips.back(), joints));
        if (tracks.back().joints != tracks.front().joints)
            throw GraphError(f + ": its skeleton gives " + std::to_string(tracks.back().joints) + " compared joints, " +
                             files.front() + " gives " + std::to_string(tracks.front().joints));
        src.file = io::data_relative(f);
        src.samples = tracks.back().frames;
        g.sources.push_back(src);
    }
    const int n = int(files.size());
    const AllPairs m = all_pairs(tracks, o.window);
    const std::vector<bool> cand = hub_candidates(m, o.hubs, o, g.transitions);
    if (log)
        *log << "graph: " << n << " files, " << m.total() << " frames, " << g.transitions << " transition points under "
             << o.threshold << " m to " << o.hubs << " hub poses\n";
    std::vector<std::vector<bool>> candidate;
    candidate.reserve(std::size_t(n));
    for (int s = 0; s < n; ++s)
        candidate.emplace_back(cand.begin() + m.offset[std::size_t(s)], cand.begin() + m.offset[std::size_t(s) + 1]);
    std::vector<GraphClip> all;
    for (int s = 0; s < n; ++s) {
        const std::vector<int> cuts = choose_cuts(tracks[std::size_t(s)].frames, candidate[std::size_t(s)], o);
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            GraphClip c;
            c.source = s;
            c.first = cuts[k];
            c.exit = cuts[k + 1];
            const auto& index = clips[std::size_t(s)].source_index;
            c.frame_first = index[std::size_t(c.first)];  // file frames (the index holds them)
            c.frame_exit = index[std::size_t(c.exit)];
            all.push_back(std::move(c));
        }
    }
    g.clips_cut = int(all.size());
    std::vector<Path> bodies;  // each source's disks centred on the body, when the graph centres them there
    if (o.centre != io::PathCentre::Root)
        for (const io::Clip& clip : clips) bodies.push_back(io::path_of(clip.animation, clip.up, o.centre));

    std::vector<std::vector<int>> succ(all.size());
    std::vector<std::vector<double>> dist(all.size());
    for (std::size_t u = 0; u < all.size(); ++u)
        for (std::size_t v = 0; v < all.size(); ++v) {
            const GraphClip &cu = all[u], &cv = all[v];
            const double d = pose_distance(tracks[std::size_t(cu.source)], cu.exit, tracks[std::size_t(cv.source)],
                                           cv.first, o.window)
                                 .distance;
            if (d < o.threshold) {
                succ[u].push_back(int(v));
                dist[u].push_back(d);
            }
        }
    int count = 0;
    const std::vector<int> comp = components(succ, count);
    std::vector<int> size(std::size_t(count), 0);
    for (int c : comp) ++size[std::size_t(c)];
    const int keep = int(std::max_element(size.begin(), size.end()) - size.begin());
    std::vector<int> id(all.size(), -1);
    for (std::size_t u = 0; u < all.size(); ++u)
        if (comp[u] == keep) {
            id[u] = int(g.clips.size());
            g.clips.push_back(all[u]);
        }
    for (std::size_t u = 0; u < all.size(); ++u) {
        if (id[u] < 0) continue;
        GraphClip& c = g.clips[std::size_t(id[u])];
        for (std::size_t k = 0; k < succ[u].size(); ++k)
            if (id[std::size_t(succ[u][k])] >= 0) {
                c.successors.push_back(id[std::size_t(succ[u][k])]);
                c.distances.push_back(util::rounded(dist[u][k], 9));
            }
        const io::Clip& source = clips[std::size_t(c.source)];
        localise(c, source, bodies.empty() ? source.path : bodies[std::size_t(c.source)], g.centre,
                 tracks[std::size_t(c.source)]);
        snap_idle(c, id[u]);
    }
    if (g.clips.size() < 2) throw GraphError("graph build: no two clips connect; raise --threshold");
    if (log)
        *log << "graph: " << all.size() << " clips cut, " << g.clips.size()
             << " in the largest strongly connected part\n";
    return g;
}

}  // namespace mobb::crowd
