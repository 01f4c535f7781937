// A motion graph's file: written as readable JSON, read with every field checked against what it means.
#include "mobb/crowd/graph/motion_graph.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "mobb/core/angle.h"
#include "mobb/util/json_text.h"

namespace mobb::crowd {

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
    if (g.centre == io::PathCentre::Enclosing)
        j["centre"] =
            "enclosing: a path's disks are the smallest holding the body; root: the root on the ground at each "
            "sample, [x, y] in the clip's frame, metres";
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
        if (!c.root.empty()) {
            J root = J::array();
            for (const glm::dvec2& p : c.root) root.push_back({p.x, p.y});
            clip["root"] = root;
        }
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
        fail(where + ".frames",
             fr + ": expected frame_begin (" + std::to_string(src.frame_begin) + ") <= first <= exit");
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

// "path": exit - first samples [x, y, r], finite, r >= 0, the first at the origin (the clip's own frame)
// unless the disks are centred on the body (read_root); "duration", when given, their duration.
void read_path(const json& c, double dt, io::PathCentre centre, GraphClip& out, const std::string& where) {
    out.path.dt = dt;
    const auto& path = field(c, "path", where);
    if (!path.is_array() || path.empty()) fail(where + ".path", "expected [[x, y, r], ...]");
    if (path.size() != std::size_t(out.exit - out.first))
        fail(where + ".path",
             std::to_string(path.size()) + " samples, \"samples\" says " + std::to_string(out.exit - out.first));
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
    if (centre == io::PathCentre::Root && (std::abs(p0.x) > 1e-6 || std::abs(p0.y) > 1e-6))
        fail(where + ".path[0]",
             "the first sample is the origin of the clip's frame, not (" + num(p0.x) + ", " + num(p0.y) + ")");
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

// "root", for disks centred on the body: a point [x, y] per sample, the first at the origin (the clip's
// frame), each inside its sample's disk (the disk holds the body, the root too).
void read_root(const json& c, GraphClip& out, const std::string& where) {
    const auto& root = field(c, "root", where);
    if (!root.is_array() || root.size() != out.path.size())
        fail(where + ".root",
             "expected [[x, y], ...], a point per sample of \"path\" (" + std::to_string(out.path.size()) + ")");
    for (std::size_t k = 0; k < root.size(); ++k) {
        const auto& p = root[k];
        const std::string place = where + ".root[" + std::to_string(k) + "]";
        if (!p.is_array() || p.size() != 2) fail(place, "expected [x, y]");
        const glm::dvec2 x{coordinate(p[0], place + "[0]"), coordinate(p[1], place + "[1]")};
        const Sample& s = out.path.samples[k];
        if (k == 0 && (std::abs(x.x) > 1e-6 || std::abs(x.y) > 1e-6))
            fail(place, "the first root is the origin of the clip's frame, not (" + num(x.x) + ", " + num(x.y) + ")");
        if (std::hypot(x.x - s.x, x.y - s.y) > s.r + 1e-6)
            fail(place, "the root (" + num(x.x) + ", " + num(x.y) + ") is outside its sample's disk");
        out.root.push_back(x);
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
        fail(where + ".source",
             std::to_string(out.source) + ": out of range (" + std::to_string(g.sources.size()) + " sources)");
    if (c.contains("kind")) {
        const auto& kind = c["kind"];
        const bool known =
            kind.is_string() && (kind == "walk" || kind == "slow" || kind == "in place" || kind == "idle");
        if (!known) fail(where + ".kind", "expected walk, slow, in place or idle");
    }
    read_ranges(c, g.sources[std::size_t(out.source)], out, where);
    read_exit(c, out, where);
    read_edges(c, g.threshold, out, where);
    read_path(c, g.dt(), g.centre, out, where);
    if (g.centre == io::PathCentre::Enclosing) read_root(c, out, where);
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
        if (!(std::abs(v - expected) <= slack)) fail(w + "." + key, num(v) + ", the clips give " + num(expected));
    };
    near("mean_duration", total / n, 1e-4);
    near("min_duration", lo, 1e-4);
    near("max_duration", hi, 1e-4);
    near("mean_successors", double(edges) / n, 1e-3);
    if (s.contains("transition_points"))
        g.transitions = integer_at_least(s["transition_points"], w + ".transition_points", 0);
    if (s.contains("clips_cut")) g.clips_cut = integer_at_least(s["clips_cut"], w + ".clips_cut", int(g.clips.size()));
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
    if (j.contains("centre")) {
        const auto& c = j["centre"];
        if (!c.is_string() || c.get<std::string>().rfind("enclosing", 0) != 0)
            fail(where + ".centre", "expected \"enclosing: ...\" (absent: disks centred on the root)");
        g.centre = io::PathCentre::Enclosing;
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
