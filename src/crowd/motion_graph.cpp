#include "mobb/crowd/motion_graph.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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
    std::string local = "assets/graphs/cmu_locomotion.json";
    if (std::filesystem::exists(local)) return local;
    return std::string(MOBB_SOURCE_DIR) + "/" + local;
}

MotionGraph build_motion_graph(const std::vector<std::string>& files, const GraphBuildOptions& o, std::ostream* log) {
    if (files.empty()) throw GraphError("graph build: no input files");
    if (!(o.fps >= kMinGraphFps && o.fps <= kMaxGraphFps) || !(o.threshold > 0) || o.window < 1 ||
        !(o.min_clip > 0) || o.max_clip < o.min_clip)
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

// Reading a graph file: every field checked against what it means, each error one line naming the
// place ("FILE: graph.clips[3].samples: ...").

using nlohmann::json;

[[noreturn]] void fail(const std::string& place, const std::string& message) {
    throw GraphError(place + ": " + message);
}

const json& field(const json& j, const char* key, const std::string& where) {
    if (!j.is_object()) fail(where, "expected an object");
    if (!j.contains(key)) throw GraphError(where + ": missing \"" + key + "\"");
    return j[key];
}

double finite(const json& v, const std::string& place) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(place, "expected a finite number");
    return v.get<double>();
}

double number(const json& j, const char* key, const std::string& where) {
    return finite(field(j, key, where), where + "." + key);
}

// An integer that fits an int (3.0 and 1e300 are not).
int integer(const json& v, const std::string& place) {
    if (!v.is_number_integer()) fail(place, "expected an integer");
    if (v.is_number_unsigned() ? v.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<int>::max())
                               : (v.get<std::int64_t>() < std::numeric_limits<int>::min() ||
                                  v.get<std::int64_t>() > std::numeric_limits<int>::max()))
        fail(place, "out of range");
    return v.get<int>();
}

int integer_at_least(const json& v, const std::string& place, int lo) {
    const int n = integer(v, place);
    if (n < lo) fail(place, std::to_string(n) + ": must be at least " + std::to_string(lo));
    return n;
}

// A pair [a, b] of integers.
std::array<int, 2> integer_pair(const json& v, const std::string& place, const char* shape) {
    if (!v.is_array() || v.size() != 2) fail(place, std::string("expected ") + shape);
    return {integer(v[0], place + "[0]"), integer(v[1], place + "[1]")};
}

std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

// What the numbers can mean: a clip's root in its own frame (within a km of where it started), a character's
// reach from its root (kGraphFps*: a rate of motion capture).
constexpr double kFar = 1000;      // metres
constexpr double kMaxRadius = 10;  // metres

double coordinate(const json& v, const std::string& place) {
    const double x = finite(v, place);
    if (std::abs(x) > kFar) fail(place, num(x) + ": farther than " + num(kFar) + " m from the clip's start");
    return x;
}

// "format" and "version", when given: this format, version 1.
void check_format(const json& j, const std::string& where) {
    if (j.contains("format") && j["format"] != "mobb motion graph")
        fail(where + ".format", "expected \"mobb motion graph\"");
    if (j.contains("version") && integer(j["version"], where + ".version") != 1)
        fail(where + ".version", "unsupported (this reads version 1)");
}

// fps > 0 with a finite dt = 1 / fps; "dt", when given, must be that dt.
double read_fps(const json& j, const std::string& where) {
    const double fps = number(j, "fps", where);
    if (!(fps > 0)) fail(where + ".fps", num(fps) + ": must be positive (frames per second)");
    if (fps < kMinGraphFps || fps > kMaxGraphFps)
        fail(where + ".fps",
             num(fps) + ": expected " + num(kMinGraphFps) + " to " + num(kMaxGraphFps) + " frames per second");
    if (j.contains("dt")) {
        const double dt = finite(j["dt"], where + ".dt");
        if (!(dt > 0)) fail(where + ".dt", "must be positive (seconds)");
        if (std::abs(dt * fps - 1.0) > 1e-9) fail(where + ".dt", num(dt) + " is not 1 / fps (fps " + num(fps) + ")");
    }
    return fps;
}

GraphSource source_from_json(const json& s, const std::string& w) {
    GraphSource out;
    const auto& f = field(s, "file", w);
    if (!f.is_string() || f.get<std::string>().empty()) fail(w + ".file", "expected a file name");
    out.file = f.get<std::string>();
    out.frame_begin = integer_at_least(field(s, "frame_begin", w), w + ".frame_begin", 0);
    if (s.contains("frame_end")) {
        out.frame_end = integer(s["frame_end"], w + ".frame_end");
        if (out.frame_end != -1 && out.frame_end <= out.frame_begin)
            fail(w + ".frame_end", std::to_string(out.frame_end) + ": must be -1 (the file's end) or after " +
                                       "frame_begin " + std::to_string(out.frame_begin));
    }
    out.samples = integer_at_least(field(s, "samples", w), w + ".samples", 1);
    return out;
}

// "samples": [first, exit] within the source (its exit pose a sample of it, at least one sample);
// "frames": the same as file frames, in order and within the source's range.
void read_ranges(const json& c, const GraphSource& src, GraphClip& out, const std::string& where) {
    const auto samples = integer_pair(field(c, "samples", where), where + ".samples", "[first, exit]");
    out.first = samples[0];
    out.exit = samples[1];
    const std::string range = "[" + std::to_string(out.first) + ", " + std::to_string(out.exit) + "]";
    if (out.first < 0 || out.exit <= out.first)
        fail(where + ".samples", range + ": expected 0 <= first < exit (a clip holds exit - first > 0 samples)");
    if (out.exit >= src.samples)
        fail(where + ".samples", range + ": its source has " + std::to_string(src.samples) + " samples");
    const auto frames = integer_pair(field(c, "frames", where), where + ".frames", "[first, exit]");
    out.frame_first = frames[0];
    out.frame_exit = frames[1];
    const std::string fr = "[" + std::to_string(out.frame_first) + ", " + std::to_string(out.frame_exit) + "]";
    if (out.frame_first < src.frame_begin || out.frame_exit < out.frame_first)
        fail(where + ".frames", fr + ": expected frame_begin (" + std::to_string(src.frame_begin) +
                                    ") <= first <= exit");
    if (src.frame_end >= 0 && out.frame_exit >= src.frame_end)
        fail(where + ".frames", fr + ": its source ends before frame " + std::to_string(src.frame_end));
}

// "exit": [x, y, heading] finite, heading in [-pi, pi]; "idle_snap": [drift, turn] of an idle clip, whose
// exit is the identity, within what the builder snaps (kIdleExit, kIdleTurn).
void read_exit(const json& c, GraphClip& out, const std::string& where) {
    const auto& exit = field(c, "exit", where);
    if (!exit.is_array() || exit.size() != 3) fail(where + ".exit", "expected [x, y, heading]");
    out.exit_x = coordinate(exit[0], where + ".exit[0]");
    out.exit_y = coordinate(exit[1], where + ".exit[1]");
    out.exit_heading = finite(exit[2], where + ".exit[2]");
    constexpr double slack = 1e-8;  // the file rounds to 9 decimals
    if (std::abs(out.exit_heading) > kPi + slack)
        fail(where + ".exit[2]", num(out.exit_heading) + ": a heading change in [-pi, pi] radians");
    if (!c.contains("idle_snap")) return;
    const auto& snap = c["idle_snap"];
    if (!snap.is_array() || snap.size() != 2) fail(where + ".idle_snap", "expected [drift, turn]");
    out.idle_drift = finite(snap[0], where + ".idle_snap[0]");
    out.idle_turn = finite(snap[1], where + ".idle_snap[1]");
    if (out.idle_drift < 0 || out.idle_drift > kIdleExit + slack)
        fail(where + ".idle_snap[0]", num(out.idle_drift) + ": an idle clip drifts 0 to " + num(kIdleExit) + " m");
    if (std::abs(out.idle_turn) > kIdleTurn + slack)
        fail(where + ".idle_snap[1]", num(out.idle_turn) + ": an idle clip turns at most " + num(kIdleTurn) + " rad");
    if (out.exit_x != 0 || out.exit_y != 0 || out.exit_heading != 0)
        fail(where + ".idle_snap", "only an idle clip has one, and its exit is [0, 0, 0]");
}

// "successors": clip ids (checked against the clip count once all are read), none twice; "distances":
// one per successor, each in [0, threshold] metres.
void read_edges(const json& c, double threshold, GraphClip& out, const std::string& where) {
    const auto& succ = field(c, "successors", where);
    if (!succ.is_array() || succ.empty()) fail(where + ".successors", "every clip needs a successor");
    for (std::size_t k = 0; k < succ.size(); ++k) {
        const int s = integer(succ[k], where + ".successors[" + std::to_string(k) + "]");
        if (std::find(out.successors.begin(), out.successors.end(), s) != out.successors.end())
            fail(where + ".successors[" + std::to_string(k) + "]", "clip " + std::to_string(s) + " listed twice");
        out.successors.push_back(s);
    }
    if (!c.contains("distances")) return;
    const auto& d = c["distances"];
    if (!d.is_array() || d.size() != succ.size())
        fail(where + ".distances", "expected one per successor (" + std::to_string(succ.size()) + ")");
    for (std::size_t k = 0; k < d.size(); ++k) {
        const std::string place = where + ".distances[" + std::to_string(k) + "]";
        const double x = finite(d[k], place);
        if (x < 0 || x > threshold)
            fail(place, num(x) + ": an edge's pose distance is in [0, threshold " + num(threshold) + "]");
        out.distances.push_back(x);
    }
}

// "path": exit - first samples [x, y, r], finite, r >= 0, the first at the origin (the clip's own frame);
// "duration", when given, their duration.
void read_path(const json& c, double dt, GraphClip& out, const std::string& where) {
    out.path.dt = dt;
    const auto& path = field(c, "path", where);
    if (!path.is_array() || path.empty()) fail(where + ".path", "expected [[x, y, r], ...]");
    if (path.size() != std::size_t(out.exit - out.first))
        fail(where + ".path", std::to_string(path.size()) + " samples, \"samples\" says " +
                                  std::to_string(out.exit - out.first));
    for (std::size_t k = 0; k < path.size(); ++k) {
        const auto& s = path[k];
        const std::string place = where + ".path[" + std::to_string(k) + "]";
        if (!s.is_array() || s.size() != 3) fail(place, "expected [x, y, r]");
        const Sample x{coordinate(s[0], place + "[0]"), coordinate(s[1], place + "[1]"), finite(s[2], place + "[2]")};
        if (x.r < 0) fail(place + "[2]", num(x.r) + ": a radius is not negative");
        if (x.r > kMaxRadius)
            fail(place + "[2]", num(x.r) + ": a character's radius is at most " + num(kMaxRadius) + " m");
        out.path.samples.push_back(x);
    }
    const Sample& p0 = out.path.samples.front();
    if (std::abs(p0.x) > 1e-6 || std::abs(p0.y) > 1e-6)
        fail(where + ".path[0]", "the first sample is the origin of the clip's frame, not (" + num(p0.x) + ", " +
                                     num(p0.y) + ")");
    try {
        validate(out.path);
    } catch (const std::invalid_argument& e) {
        fail(where + ".path", e.what());
    }
    if (c.contains("duration")) {
        const double d = finite(c["duration"], where + ".duration");
        if (std::abs(d - out.path.duration()) > 1e-6 + 1e-9 * out.path.duration())
            fail(where + ".duration", num(d) + " s, its " + std::to_string(out.path.size()) + " samples last " +
                                          num(out.path.duration()) + " s");
    }
}

GraphClip clip_from_json(const json& c, const MotionGraph& g, std::size_t id, const std::string& where) {
    if (!c.is_object()) fail(where, "expected an object");
    GraphClip out;
    if (c.contains("id")) {
        const int given = integer(c["id"], where + ".id");
        if (given != int(id))
            fail(where + ".id", std::to_string(given) + ": the clip's place in \"clips\" is " + std::to_string(id));
    }
    out.source = integer(field(c, "source", where), where + ".source");
    if (out.source < 0 || out.source >= int(g.sources.size()))
        fail(where + ".source", std::to_string(out.source) + ": out of range (" + std::to_string(g.sources.size()) +
                                    " sources)");
    if (c.contains("kind")) {
        const auto& kind = c["kind"];
        const bool known =
            kind.is_string() && (kind == "walk" || kind == "slow" || kind == "in place" || kind == "idle");
        if (!known) fail(where + ".kind", "expected walk, slow, in place or idle");
    }
    read_ranges(c, g.sources[std::size_t(out.source)], out, where);
    read_exit(c, out, where);
    read_edges(c, g.threshold, out, where);
    read_path(c, g.dt(), out, where);
    return out;
}

// "stats", when given: what the clips add up to (clips, edges, durations rounded to 4 decimals, mean
// successors to 3); transition_points and clips_cut, build statistics, kept.
void read_stats(const json& j, MotionGraph& g, const std::string& where) {
    if (!j.contains("stats")) return;
    const json& s = j["stats"];
    const std::string w = where + ".stats";
    if (!s.is_object()) fail(w, "expected an object");
    std::size_t edges = 0;
    double total = 0, lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const GraphClip& c : g.clips) {
        edges += c.successors.size();
        total += c.path.duration();
        lo = std::min(lo, c.path.duration());
        hi = std::max(hi, c.path.duration());
    }
    const double n = double(g.clips.size());
    const auto count = [&](const char* key, std::size_t expected, const char* what) {
        if (!s.contains(key)) return;
        const int v = integer(s[key], w + "." + key);
        if (v < 0 || std::size_t(v) != expected)
            fail(w + "." + key, std::to_string(v) + ", the graph has " + std::to_string(expected) + " " + what);
    };
    count("clips", g.clips.size(), "clips");
    count("edges", edges, "edges");
    const auto near = [&](const char* key, double expected, double slack) {
        if (!s.contains(key)) return;
        const double v = finite(s[key], w + "." + key);
        if (!(std::abs(v - expected) <= slack))
            fail(w + "." + key, num(v) + ", the clips give " + num(expected));
    };
    near("mean_duration", total / n, 1e-4);
    near("min_duration", lo, 1e-4);
    near("max_duration", hi, 1e-4);
    near("mean_successors", double(edges) / n, 1e-3);
    if (s.contains("transition_points"))
        g.transitions = integer_at_least(s["transition_points"], w + ".transition_points", 0);
    if (s.contains("clips_cut"))
        g.clips_cut = integer_at_least(s["clips_cut"], w + ".clips_cut", int(g.clips.size()));
}

}  // namespace

MotionGraph graph_from_json(const json& j, const std::string& where) {
    if (!j.is_object()) fail(where, "expected an object");
    check_format(j, where);
    MotionGraph g;
    g.fps = read_fps(j, where);
    g.threshold = number(j, "threshold", where);
    if (!(g.threshold > 0)) fail(where + ".threshold", num(g.threshold) + ": must be positive (metres)");
    g.window = integer_at_least(field(j, "window", where), where + ".window", 1);
    if (j.contains("command")) {
        if (!j["command"].is_string()) fail(where + ".command", "expected a string");
        g.command = j["command"].get<std::string>();
    }
    if (j.contains("joints")) {
        if (!j["joints"].is_array()) fail(where + ".joints", "expected an array of joint names");
        for (std::size_t k = 0; k < j["joints"].size(); ++k) {
            const auto& n = j["joints"][k];
            if (!n.is_string()) fail(where + ".joints[" + std::to_string(k) + "]", "expected a joint name");
            g.joints.push_back(n.get<std::string>());
        }
    }
    const auto& sources = field(j, "sources", where);
    if (!sources.is_array()) fail(where + ".sources", "expected an array");  // clips name their source
    for (std::size_t k = 0; k < sources.size(); ++k)
        g.sources.push_back(source_from_json(sources[k], where + ".sources[" + std::to_string(k) + "]"));
    const auto& clips = field(j, "clips", where);
    if (!clips.is_array() || clips.empty()) fail(where + ".clips", "expected a non-empty array");
    for (std::size_t k = 0; k < clips.size(); ++k)
        g.clips.push_back(clip_from_json(clips[k], g, k, where + ".clips[" + std::to_string(k) + "]"));
    for (std::size_t k = 0; k < g.clips.size(); ++k) {
        const auto& succ = g.clips[k].successors;
        for (std::size_t e = 0; e < succ.size(); ++e)
            if (succ[e] < 0 || succ[e] >= int(g.clips.size()))
                fail(where + ".clips[" + std::to_string(k) + "].successors[" + std::to_string(e) + "]",
                     "clip " + std::to_string(succ[e]) + " does not exist (" + std::to_string(g.clips.size()) +
                         " clips)");
    }
    read_stats(j, g, where);
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
