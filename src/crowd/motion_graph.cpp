#include "mobb/crowd/motion_graph.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <ostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "mobb/core/angle.h"
#include "mobb/crowd/pose_distance.h"
#include "mobb/io/load.h"
#include "mobb/util/json_text.h"

namespace mobb::crowd {

namespace {

double wrap_angle(double a) { return std::remainder(a, 2.0 * kPi); }

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

double reach_of(const Path& p) {
    double d = 0;
    for (const Sample& s : p.samples) d = std::max(d, std::hypot(s.x - p.samples[0].x, s.y - p.samples[0].y));
    return d;
}

// An idle clip (ClipKind::Idle, before its snap) loops in place: its exit becomes the identity.
void snap_idle(GraphClip& c, int id) {
    const bool loops = std::find(c.successors.begin(), c.successors.end(), id) != c.successors.end();
    if (!loops || reach_of(c.path) > kIdleReach || std::hypot(c.exit_x, c.exit_y) > kIdleExit ||
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
                    const std::size_t gi = std::size_t(m.offset[a] + i), gj = std::size_t(m.offset[b] + j);
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
            for (int d = -spread; d <= spread; ++d)
                if (g + d >= 0 && g + d < m.total()) near[std::size_t(g + d)] = true;
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

// The clip's path in its own frame, and the exit transform.
void localise(GraphClip& c, const io::Clip& clip, const PoseTrack& track) {
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
    for (int i = c.first; i < c.exit; ++i) {
        const Sample& s = clip.path.samples[std::size_t(i)];
        Sample l;
        local(s.x, s.y, l.x, l.y);
        l.r = util::rounded(s.r);
        c.path.samples.push_back(l);
    }
    const Sample& e = clip.path.samples[std::size_t(c.exit)];
    local(e.x, e.y, c.exit_x, c.exit_y);
    c.exit_heading = util::rounded(wrap_angle(track.heading[std::size_t(c.exit)] - h), 9);
}

}  // namespace

ClipKind kind_of(const GraphClip& c, int id) {
    const double reach = reach_of(c.path), exit = std::hypot(c.exit_x, c.exit_y);
    const bool loops = std::find(c.successors.begin(), c.successors.end(), id) != c.successors.end();
    if (loops && reach <= kIdleReach && c.exit_x == 0 && c.exit_y == 0 && c.exit_heading == 0) return ClipKind::Idle;
    if (reach <= kInPlaceReach && exit <= kInPlaceExit) return ClipKind::InPlace;
    return exit / c.path.duration() < kWalking ? ClipKind::Slow : ClipKind::Walk;
}

const char* to_string(ClipKind kind) {
    switch (kind) {
        case ClipKind::Walk: return "walk";
        case ClipKind::Slow: return "slow";
        case ClipKind::InPlace: return "in place";
        case ClipKind::Idle: return "idle";
    }
    return "?";
}

Placement MotionGraph::next(const Placement& p, int clip) const { return next(p, Rigid2::of(p), clip); }

Placement MotionGraph::next(const Placement& p, const Rigid2& m, int clip) const {
    const GraphClip& c = clips[std::size_t(clip)];
    return {p.x + m.c * c.exit_x - m.s * c.exit_y, p.y + m.s * c.exit_x + m.c * c.exit_y, p.theta + c.exit_heading,
            p.t0 + double(c.path.size()) * dt()};
}

io::Clip load_graph_source(const MotionGraph& g, int source) {
    const GraphSource& src = g.sources.at(std::size_t(source));
    // Frames dropped first, then resampled (LoadOptions applies them in that order), as the build did.
    io::LoadOptions lo;
    lo.fps = g.fps;
    lo.frame_begin = src.frame_begin;
    lo.frame_end = src.frame_end;
    const std::string file = io::resolve_data_file(src.file);
    io::Clip clip = io::load_clip(file, lo);
    if (int(clip.path.size()) != src.samples)
        throw GraphError(file + ": " + std::to_string(clip.path.size()) + " samples at " + std::to_string(g.fps) +
                         " fps, the graph expects " + std::to_string(src.samples) + " (a different file?)");
    return clip;
}

std::string default_graph_file() {
    const std::string local = "assets/graphs/cmu_locomotion.json";
    if (std::filesystem::exists(local)) return local;
    return std::string(MOBB_SOURCE_DIR) + "/" + local;
}

MotionGraph build_motion_graph(const std::vector<std::string>& files, const GraphBuildOptions& o, std::ostream* log) {
    if (files.empty()) throw GraphError("graph build: no input files");
    if (!(o.fps > 0) || !(o.threshold > 0) || o.window < 1 || !(o.min_clip > 0) || o.max_clip < o.min_clip)
        throw GraphError("graph build: invalid options");
    MotionGraph g;
    g.fps = o.fps;
    g.threshold = o.threshold;
    g.window = o.window;
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
        localise(c, clips[std::size_t(c.source)], tracks[std::size_t(c.source)]);
        snap_idle(c, id[u]);
    }
    if (g.clips.size() < 2) throw GraphError("graph build: no two clips connect; raise --threshold");
    if (log)
        *log << "graph: " << all.size() << " clips cut, " << g.clips.size()
             << " in the largest strongly connected part\n";
    return g;
}

std::string graph_to_text(const MotionGraph& g) {
    using J = nlohmann::ordered_json;
    J j;
    j["format"] = "mobb motion graph";
    j["version"] = 1;
    j["comment"] =
        "Clips of real mocap joined where poses match (Kovar et al. 2002). Units: metres, seconds, "
        "radians. A clip is samples [first, exit) of its source at fps; its path is in its own frame "
        "(root of sample first at the origin, facing +x); exit = [x, y, heading change] of sample exit, "
        "where a successor starts. kind: walk, slow (starting, stopping), in place (turning on the spot), idle "
        "(standing and looping in place, what an agent stops with: its exit is snapped to the identity; idle_snap "
        "gives how far its root really moved, metres, and turned, radians, over the clip in the take).";
    j["command"] = g.command;
    j["fps"] = g.fps;
    j["dt"] = g.dt();
    j["threshold"] = g.threshold;
    j["window"] = g.window;
    j["heading"] = "facing direction: perpendicular to left-minus-right of thighs and upper arms, mean over +-2 frames";
    j["joints"] = g.joints;
    J sources = J::array();
    for (const GraphSource& s : g.sources)
        sources.push_back(
            {{"file", s.file}, {"frame_begin", s.frame_begin}, {"frame_end", s.frame_end}, {"samples", s.samples}});
    j["sources"] = sources;
    double total = 0, lo = 1e300, hi = 0;
    std::size_t edges = 0;
    for (const GraphClip& c : g.clips) {
        total += c.path.duration();
        lo = std::min(lo, c.path.duration());
        hi = std::max(hi, c.path.duration());
        edges += c.successors.size();
    }
    const double count = double(std::max<std::size_t>(1, g.clips.size()));
    j["stats"] = {{"clips", g.clips.size()},
                  {"edges", edges},
                  {"mean_duration", util::rounded(total / count, 4)},
                  {"min_duration", util::rounded(lo, 4)},
                  {"max_duration", util::rounded(hi, 4)},
                  {"mean_successors", util::rounded(double(edges) / count, 3)},
                  {"transition_points", g.transitions},
                  {"clips_cut", g.clips_cut}};
    J clips = J::array();
    for (std::size_t k = 0; k < g.clips.size(); ++k) {
        const GraphClip& c = g.clips[k];
        J path = J::array();
        for (const Sample& s : c.path.samples) path.push_back({s.x, s.y, s.r});
        J clip = {{"id", k},
                  {"file", g.sources[std::size_t(c.source)].file},
                  {"source", c.source},
                  {"kind", to_string(kind_of(c, int(k)))},
                  {"samples", {c.first, c.exit}},
                  {"frames", {c.frame_first, c.frame_exit}},
                  {"duration", util::rounded(c.path.duration(), 6)},
                  {"exit", {c.exit_x, c.exit_y, c.exit_heading}}};
        if (c.idle_drift != 0 || c.idle_turn != 0) clip["idle_snap"] = {c.idle_drift, c.idle_turn};
        clip["successors"] = c.successors;
        clip["distances"] = c.distances;
        clip["path"] = path;
        clips.push_back(clip);
    }
    j["clips"] = clips;
    return util::readable_json(j);
}

namespace {

const nlohmann::json& field(const nlohmann::json& j, const char* key, const std::string& where) {
    if (!j.is_object() || !j.contains(key)) throw GraphError(where + ": missing \"" + key + "\"");
    return j[key];
}

double number(const nlohmann::json& j, const char* key, const std::string& where) {
    const nlohmann::json& v = field(j, key, where);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
        throw GraphError(where + "." + key + ": expected a finite number");
    return v.get<double>();
}

int integer(const nlohmann::json& v, const std::string& where) {
    if (!v.is_number_integer()) throw GraphError(where + ": expected an integer");
    return v.get<int>();
}

GraphClip clip_from_json(const nlohmann::json& c, const MotionGraph& g, const std::string& where) {
    GraphClip out;
    out.source = integer(field(c, "source", where), where + ".source");
    if (out.source < 0 || out.source >= int(g.sources.size())) throw GraphError(where + ".source: out of range");
    const auto& samples = field(c, "samples", where);
    const auto& frames = field(c, "frames", where);
    if (!samples.is_array() || samples.size() != 2 || !frames.is_array() || frames.size() != 2)
        throw GraphError(where + ": \"samples\" and \"frames\" must be [first, exit]");
    out.first = integer(samples[0], where + ".samples[0]");
    out.exit = integer(samples[1], where + ".samples[1]");
    out.frame_first = integer(frames[0], where + ".frames[0]");
    out.frame_exit = integer(frames[1], where + ".frames[1]");
    const auto& exit = field(c, "exit", where);
    if (!exit.is_array() || exit.size() != 3) throw GraphError(where + ".exit: expected [x, y, heading]");
    for (const auto& v : exit)
        if (!v.is_number()) throw GraphError(where + ".exit: expected numbers");
    out.exit_x = exit[0].get<double>();
    out.exit_y = exit[1].get<double>();
    out.exit_heading = exit[2].get<double>();
    if (c.contains("idle_snap") && c["idle_snap"].is_array() && c["idle_snap"].size() == 2 &&
        c["idle_snap"][0].is_number() && c["idle_snap"][1].is_number()) {
        out.idle_drift = c["idle_snap"][0].get<double>();
        out.idle_turn = c["idle_snap"][1].get<double>();
    }
    const auto& succ = field(c, "successors", where);
    if (!succ.is_array() || succ.empty()) throw GraphError(where + ".successors: every clip needs a successor");
    for (std::size_t k = 0; k < succ.size(); ++k)
        out.successors.push_back(integer(succ[k], where + ".successors[" + std::to_string(k) + "]"));
    if (c.contains("distances") && c["distances"].is_array())
        for (const auto& d : c["distances"])
            if (d.is_number()) out.distances.push_back(d.get<double>());
    out.path.dt = g.dt();
    const auto& path = field(c, "path", where);
    if (!path.is_array() || path.empty()) throw GraphError(where + ".path: expected [[x, y, r], ...]");
    for (std::size_t k = 0; k < path.size(); ++k) {
        const auto& s = path[k];
        if (!s.is_array() || s.size() != 3 || !s[0].is_number() || !s[1].is_number() || !s[2].is_number())
            throw GraphError(where + ".path[" + std::to_string(k) + "]: expected [x, y, r]");
        out.path.samples.push_back({s[0].get<double>(), s[1].get<double>(), s[2].get<double>()});
    }
    try {
        validate(out.path);
    } catch (const std::invalid_argument& e) {
        throw GraphError(where + ".path: " + e.what());
    }
    return out;
}

}  // namespace

MotionGraph graph_from_json(const nlohmann::json& j, const std::string& where) {
    MotionGraph g;
    g.fps = number(j, "fps", where);
    if (!(g.fps > 0)) throw GraphError(where + ".fps: must be positive");
    g.threshold = number(j, "threshold", where);
    g.window = int(number(j, "window", where));
    if (j.contains("command") && j["command"].is_string()) g.command = j["command"].get<std::string>();
    if (j.contains("joints") && j["joints"].is_array())
        for (const auto& n : j["joints"])
            if (n.is_string()) g.joints.push_back(n.get<std::string>());
    const auto& sources = field(j, "sources", where);
    if (!sources.is_array()) throw GraphError(where + ".sources: expected an array");
    for (std::size_t k = 0; k < sources.size(); ++k) {
        const std::string w = where + ".sources[" + std::to_string(k) + "]";
        const auto& f = field(sources[k], "file", w);
        if (!f.is_string()) throw GraphError(w + ".file: expected a string");
        const int end = sources[k].contains("frame_end") ? int(number(sources[k], "frame_end", w)) : -1;
        g.sources.push_back({f.get<std::string>(), int(number(sources[k], "frame_begin", w)), end,
                             int(number(sources[k], "samples", w))});
    }
    const auto& clips = field(j, "clips", where);
    if (!clips.is_array() || clips.empty()) throw GraphError(where + ".clips: expected a non-empty array");
    for (std::size_t k = 0; k < clips.size(); ++k)
        g.clips.push_back(clip_from_json(clips[k], g, where + ".clips[" + std::to_string(k) + "]"));
    for (std::size_t k = 0; k < g.clips.size(); ++k)
        for (int s : g.clips[k].successors)
            if (s < 0 || s >= int(g.clips.size()))
                throw GraphError(where + ".clips[" + std::to_string(k) + "].successors: clip " + std::to_string(s) +
                                 " does not exist");
    return g;
}

MotionGraph load_graph(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw GraphError(file + ": cannot open");
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded()) throw GraphError(file + ": not valid JSON");
    return graph_from_json(j, file + ": graph");
}

void save_graph(const MotionGraph& graph, const std::string& file) {
    std::ofstream out(file);
    if (!out) throw GraphError(file + ": cannot write");
    out << graph_to_text(graph);
    if (!out) throw GraphError(file + ": write failed");
}

}  // namespace mobb::crowd
