#include "mobb/crowd/record.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "mobb/crowd/motion_graph.h"
#include "mobb/util/json_text.h"

namespace mobb::crowd {

const char* to_string(AtGoal at_goal) { return at_goal == AtGoal::Leave ? "leave" : "stay"; }

std::optional<AtGoal> at_goal_of(const std::string& name) {
    if (name == "stay") return AtGoal::Stay;
    if (name == "leave") return AtGoal::Leave;
    return std::nullopt;
}

namespace {

// Whether agent a plays a fallback clip at frame f (clips are in time order).
bool fallback_at(const AgentTrack& t, std::int64_t f) {
    auto it = std::upper_bound(t.clips.begin(), t.clips.end(), f,
                               [](std::int64_t x, const PlacedClip& c) { return x < c.start; });
    return it != t.clips.begin() && std::prev(it)->fallback;
}

// The agents of one frame sorted into a flat grid over their bounding rectangle (a counting sort, so
// linear in the agents), their disks stored in cell order so that scans read contiguous memory. Cells
// are wider than any contact distance, so contacts are between agents of neighbouring cells, and there
// are at most about 2 n cells however far agents stray.
class FrameGrid {
public:
    struct Disk {
        double x, y, r;
        int agent;
    };

    /// Sorts the n disks of one frame (the agents in the run then).
    void build(const Disk* frame, std::size_t n, double reach) {
        x0_ = y0_ = 1e300;
        double x1 = -1e300, y1 = -1e300;
        for (std::size_t a = 0; a < n; ++a)
            x0_ = std::min(x0_, frame[a].x), y0_ = std::min(y0_, frame[a].y), x1 = std::max(x1, frame[a].x),
            y1 = std::max(y1, frame[a].y);
        const double w = x1 - x0_, h = y1 - y0_, count = double(n);
        // The margin keeps rounding of (x - x0) / cell from putting two agents closer than `reach` two
        // cells apart.
        cell_ = std::max({reach * (1 + 1e-9), std::sqrt(w * h / count), (w + h) / count, 1e-6});
        nx_ = int(w / cell_) + 1, ny_ = int(h / cell_) + 1;
        cell_of_.resize(n);
        first_.assign(std::size_t(nx_) * std::size_t(ny_) + 1, 0);
        for (std::size_t a = 0; a < n; ++a) {
            cell_of_[a] = cell(column(frame[a].x - x0_, nx_), column(frame[a].y - y0_, ny_));
            ++first_[cell_of_[a] + 1];
        }
        for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
        disks_.resize(n);
        fill_.assign(first_.begin(), first_.end() - 1);
        for (std::size_t a = 0; a < n; ++a) disks_[fill_[cell_of_[a]]++] = frame[a];
    }

    /// Calls f(a, b) once for every unordered pair of agents whose disks overlap (|p_a - p_b| < r_a + r_b).
    template <class F>
    void overlaps(F&& f) const {
        for (int ix = 0; ix < nx_; ++ix)
            for (int iy = 0; iy < ny_; ++iy) {
                const std::size_t c = cell(ix, iy);
                for (std::size_t i = first_[c]; i < first_[c + 1]; ++i) {
                    test(i, i + 1, first_[c + 1], f);                            // the rest of its cell
                    if (iy + 1 < ny_) test(i, first_[c + 1], first_[c + 2], f);  // the cell above
                    if (ix + 1 < nx_) {                                          // the three cells to the right
                        const std::size_t lo = cell(ix + 1, std::max(0, iy - 1)),
                                          hi = cell(ix + 1, std::min(ny_ - 1, iy + 1));
                        test(i, first_[lo], first_[hi + 1], f);
                    }
                }
            }
    }

private:
    int column(double d, int n) const { return std::clamp(int(d / cell_), 0, n - 1); }
    std::size_t cell(int ix, int iy) const { return std::size_t(ix) * std::size_t(ny_) + std::size_t(iy); }

    template <class F>
    void test(std::size_t i, std::size_t lo, std::size_t hi, F& f) const {
        const Disk& a = disks_[i];
        for (std::size_t j = lo; j < hi; ++j) {
            const Disk& b = disks_[j];
            const double dx = a.x - b.x, dy = a.y - b.y, r = a.r + b.r;
            if (dx * dx + dy * dy < r * r) f(a.agent, b.agent);
        }
    }

    double x0_ = 0, y0_ = 0, cell_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::size_t> cell_of_, first_, fill_;
    std::vector<Disk> disks_;
};

}  // namespace

std::vector<Contact> frame_contacts(const Record& record) {
    const std::size_t n = record.tracks.size();
    std::vector<Contact> out;
    if (n < 2) return out;
    // The samples are stored per agent; frames are scanned a block at a time from a frame-major copy,
    // so every track is read in runs rather than one cache line per agent per frame.
    constexpr std::int64_t kBlock = 32;
    std::vector<FrameGrid::Disk> block(std::size_t(kBlock) * n);
    std::vector<std::size_t> in_run;
    FrameGrid grid;
    const auto by_pair = [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
    for (std::int64_t f0 = 0; f0 < record.frames; f0 += kBlock) {
        const std::int64_t frames = std::min(kBlock, record.frames - f0);
        double rmax = 0;  // of the block: contacts are closer than 2 rmax
        in_run.assign(std::size_t(frames), 0);  // per frame: agents still in the run (none left yet)
        for (std::size_t a = 0; a < n; ++a) {
            const auto& samples = record.tracks[a].samples;
            const std::int64_t until = std::min(frames, std::int64_t(samples.size()) - f0);
            for (std::int64_t k = 0; k < until; ++k) {
                const auto& s = samples[std::size_t(f0 + k)];
                block[std::size_t(k) * n + in_run[std::size_t(k)]++] = {s[1], s[2], s[3], int(a)};
                rmax = std::max(rmax, s[3]);
            }
        }
        for (std::int64_t k = 0; k < frames; ++k) {
            const std::int64_t f = f0 + k;
            grid.build(&block[std::size_t(k) * n], in_run[std::size_t(k)], 2 * rmax);
            const std::size_t first = out.size();
            grid.overlaps([&](int a, int b) { out.push_back({f, std::min(a, b), std::max(a, b), false}); });
            std::sort(out.begin() + std::ptrdiff_t(first), out.end(), by_pair);
            for (std::size_t c = first; c < out.size(); ++c)
                out[c].excused = fallback_at(record.tracks[std::size_t(out[c].a)], f) ||
                                 fallback_at(record.tracks[std::size_t(out[c].b)], f);
        }
    }
    return out;
}

namespace {

// The escape clips and held ground choice point `cp` reserved for `agent`: its own or a reroute's.
struct ReservedPlan {
    const std::vector<FramedClip>* escape = nullptr;
    std::optional<HeldGround> hold;
};

ReservedPlan reserved_plan(const ChoicePoint& cp, int agent) {
    if (agent == cp.agent) {
        ReservedPlan p{&cp.escape, std::nullopt};
        if (cp.holds) p.hold = HeldGround{cp.hold, cp.hold_frame};
        return p;
    }
    for (const ReroutedPlan& r : cp.reroutes)
        if (r.agent == agent) return {&r.escape, HeldGround{r.hold, r.hold_frame}};
    throw std::out_of_range("no plan of that agent at that commit");
}

}  // namespace

std::optional<FramedClip> query_clip(const Record& r, const CandidateQuery& q) {
    if (q.agent < 0 || q.piece < 0) return std::nullopt;
    const ChoicePoint& cp = r.choices.at(std::size_t(q.commit));
    if (q.piece > 0) return reserved_plan(cp, q.agent).escape->at(std::size_t(q.piece - 1));
    const auto& clips = r.tracks.at(std::size_t(q.agent)).clips;
    const auto it = std::lower_bound(clips.begin(), clips.end(), std::int64_t(q.commit),
                                     [](const PlacedClip& c, std::int64_t x) { return c.commit < x; });
    if (it == clips.end() || it->commit != q.commit) throw std::out_of_range("no clip of that commit");
    return FramedClip{it->clip, it->start, it->place};
}

std::optional<HeldGround> query_hold(const Record& r, const CandidateQuery& q) {
    if (q.agent < 0 || q.piece != -1 || q.commit < 0) return std::nullopt;
    const std::optional<HeldGround> h = reserved_plan(r.choices.at(std::size_t(q.commit)), q.agent).hold;
    if (!h) throw std::out_of_range("no held ground in that plan");
    return h;
}

namespace {

using J = nlohmann::ordered_json;

J world_json(const World& w) {
    if (w.x0 == 0 && w.y0 == 0) return {w.x1, w.y1};
    return {w.x0, w.y0, w.x1, w.y1};
}

J obstacles_json(const World& w) {
    J out = J::array();
    for (const Polygon& p : w.obstacles) {
        J poly = J::array();
        for (const auto& v : p.vertices) poly.push_back({v[0], v[1]});
        out.push_back(poly);
    }
    return out;
}

J track_json(const AgentTrack& t) {
    J clips = J::array();
    for (const PlacedClip& c : t.clips)
        clips.push_back({{"clip", c.clip},
                         {"start", c.start},
                         {"place", {c.place.x, c.place.y, c.place.theta, c.place.t0}},
                         {"fallback", c.fallback},
                         {"commit", c.commit}});
    J samples = J::array();
    for (const auto& s : t.samples) samples.push_back({s[0], s[1], s[2], s[3]});
    J out = J::object();
    if (t.goals.size() == 1) out["goal"] = {t.goals[0][0], t.goals[0][1]};
    if (t.goals.size() > 1) {
        out["goals"] = J::array();
        for (const auto& g : t.goals) out["goals"].push_back({g[0], g[1]});
    }
    if (t.at_goal == AtGoal::Leave) out["at_goal"] = to_string(t.at_goal);
    if (t.left_frame) out["left_frame"] = *t.left_frame;
    out["clips"] = clips;
    out["samples"] = samples;
    return out;
}

J escape_json(const std::vector<FramedClip>& clips) {
    J escape = J::array();
    for (const FramedClip& e : clips) escape.push_back({e.clip, e.frame, e.place.x, e.place.y, e.place.theta});
    return escape;
}

J hold_json(const std::array<double, 3>& h, std::int64_t frame) { return {h[0], h[1], h[2], frame}; }

J plan_json(const ChoicePoint& c) {
    J out = {{"escape", escape_json(c.escape)}};
    if (c.holds) out["hold"] = hold_json(c.hold, c.hold_frame);
    if (!c.intended.empty()) out["intended"] = escape_json(c.intended);
    if (c.reroutes.empty()) return out;
    J reroutes = J::array();
    for (const ReroutedPlan& r : c.reroutes)
        reroutes.push_back(
            {{"agent", r.agent}, {"escape", escape_json(r.escape)}, {"hold", hold_json(r.hold, r.hold_frame)}});
    out["reroutes"] = reroutes;
    return out;
}

J choice_json(const ChoicePoint& c, double dt) {
    J cands = J::array();
    for (const Candidate& k : c.candidates) {
        J against = J::array();
        for (const CandidateQuery& q : k.against) against.push_back({q.agent, q.commit, q.piece, q.mine, int(q.hit)});
        cands.push_back(
            {{"clip", k.clip}, {"outside", k.outside}, {"queries", k.queries}, {"hits", k.hits}, {"against", against}});
        if (k.crowded) cands.back()["crowded"] = true;
    }
    return {{"agent", c.agent},     {"frame", c.frame},     {"t", util::rounded(double(c.frame) * dt, 9)},
            {"taken", c.taken},     {"outcome", c.outcome}, {"fallback", c.fallback},
            {"queries", c.queries}, {"tests2d", c.tests2d}, {"tests3d", c.tests3d},
            {"samples", c.samples}, {"pruned", c.pruned},   {"plan", plan_json(c)},
            {"candidates", cands}};
}

}  // namespace

namespace {

// Reading a record: every field checked against what it means. A problem throws Bad "PLACE: message"
// (PLACE like tracks[2].samples[7][3]); load_record puts the file in front.
using json = nlohmann::json;

struct Bad : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& place, const std::string& message) { throw Bad(place + ": " + message); }

std::string at(const std::string& place, std::size_t k) { return place + "[" + std::to_string(k) + "]"; }
std::string dot(const std::string& place, const char* key) { return place.empty() ? key : place + "." + key; }

std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

const json& need(const json& j, const char* key, const std::string& place) {
    if (!j.is_object()) fail(place.empty() ? "record" : place, "expected an object");
    if (!j.contains(key)) fail(place.empty() ? "record" : place, std::string("missing \"") + key + "\"");
    return j[key];
}

const json& array(const json& v, const std::string& place, const char* what) {
    if (!v.is_array()) fail(place, std::string("expected ") + what);
    return v;
}

// An array of exactly n elements.
const json& tuple(const json& v, std::size_t n, const std::string& place, const char* what) {
    if (!v.is_array() || v.size() != n) fail(place, std::string("expected ") + what);
    return v;
}

double finite(const json& v, const std::string& place) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(place, "expected a finite number");
    return v.get<double>();
}

// Where a crowd can be: within 1000 km of the origin; how far a character reaches from its root: 10 m.
constexpr double kFar = 1e6, kMaxRadius = 10;  // metres

double coordinate(const json& v, const std::string& place) {
    const double x = finite(v, place);
    if (std::abs(x) > kFar) fail(place, num(x) + ": farther than " + num(kFar) + " m from the origin");
    return x;
}

double radius(const json& v, const std::string& place) {
    const double x = finite(v, place);
    if (x < 0) fail(place, num(x) + ": a radius is not negative");
    if (x > kMaxRadius) fail(place, num(x) + ": a character's radius is at most " + num(kMaxRadius) + " m");
    return x;
}

// An integer in [lo, hi] (3.0 and 1e300 are not integers).
std::int64_t integer(const json& v, const std::string& place, std::int64_t lo, std::int64_t hi) {
    if (!v.is_number_integer()) fail(place, "expected an integer");
    if (v.is_number_unsigned() && v.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<std::int64_t>::max()))
        fail(place, "out of range");
    const std::int64_t n = v.get<std::int64_t>();
    if (n < lo || n > hi)
        fail(place, std::to_string(n) + ": expected " +
                        (hi == std::numeric_limits<std::int64_t>::max() || hi == std::numeric_limits<int>::max()
                             ? "at least " + std::to_string(lo)
                             : std::to_string(lo) + " to " + std::to_string(hi)));
    return n;
}

int index(const json& v, const std::string& place, std::int64_t lo, std::int64_t hi) {
    return int(integer(v, place, lo, std::min<std::int64_t>(hi, std::numeric_limits<int>::max())));
}

std::uint64_t counter(const json& v, const std::string& place) {
    if (!v.is_number_unsigned()) fail(place, "expected a count (an integer, not negative)");
    return v.get<std::uint64_t>();
}

bool boolean(const json& v, const std::string& place) {
    if (!v.is_boolean()) fail(place, "expected true or false");
    return v.get<bool>();
}

std::string text(const json& v, const std::string& place) {
    if (!v.is_string()) fail(place, "expected a string");
    return v.get<std::string>();
}

constexpr std::int64_t kNoLimit = std::numeric_limits<std::int64_t>::max();

// Time t of global frame k (t = k * dt), up to the rounding of the text.
void check_time(double t, std::int64_t frame, double dt, double slack, const std::string& place) {
    const double want = double(frame) * dt;
    if (!(std::abs(t - want) <= slack * (1 + std::abs(want))))
        fail(place, num(t) + " s, frame " + std::to_string(frame) + " starts at " + num(want) + " s");
}

void check_header(const json& j) {
    if (j.contains("format") && j["format"] != "mobb crowd record") fail("format", "expected \"mobb crowd record\"");
    if (j.contains("version")) integer(j["version"], "version", 1, 2);
}

// "world": [W, H] for [0, W] x [0, H], or [x0, y0, x1, y1], a rectangle of positive area; "walls";
// "obstacles": polygons of two or more finite vertices.
World world_of(const json& j) {
    World w;
    const json& v = need(j, "world", "");
    if (!v.is_array() || (v.size() != 2 && v.size() != 4)) fail("world", "expected [W, H] or [x0, y0, x1, y1]");
    if (v.size() == 4) {
        w.x0 = coordinate(v[0], "world[0]"), w.y0 = coordinate(v[1], "world[1]");
        w.x1 = coordinate(v[2], "world[2]"), w.y1 = coordinate(v[3], "world[3]");
        if (!(w.x0 < w.x1 && w.y0 < w.y1)) fail("world", "expected [x0, y0, x1, y1] with x0 < x1, y0 < y1");
    } else {
        w.x1 = coordinate(v[0], "world[0]"), w.y1 = coordinate(v[1], "world[1]");
        if (!(w.x1 > 0 && w.y1 > 0)) fail("world", "expected [W, H] with W > 0, H > 0");
    }
    w.walls = j.contains("walls") ? boolean(j["walls"], "walls") : false;
    if (!j.contains("obstacles")) return w;
    const json& obstacles = array(j["obstacles"], "obstacles", "an array of polygons");
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        const std::string place = at("obstacles", k);
        const json& poly = array(obstacles[k], place, "a polygon [[x, y], ...]");
        if (poly.size() < 2) fail(place, "a polygon has two or more vertices");
        Polygon p;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const json& q = tuple(poly[i], 2, at(place, i), "[x, y]");
            p.vertices.push_back({coordinate(q[0], at(at(place, i), 0)), coordinate(q[1], at(at(place, i), 1))});
        }
        w.obstacles.push_back(std::move(p));
    }
    return w;
}

// A track's clips: graph clip ids, the first from frame 0, then starting in time order inside the run,
// each placed at its start time (t0 = start * dt), committed by choice points in order (-1: none, the
// agent's first clip; the choice points' count is checked once they are read).
PlacedClip placed_clip_of(const json& c, const Record& r, const PlacedClip* before, const std::string& w) {
    PlacedClip out;
    out.clip = index(need(c, "clip", w), dot(w, "clip"), 0, kNoLimit);
    out.start = integer(need(c, "start", w), dot(w, "start"), 0, r.frames - 1);
    if (!before && out.start != 0)
        fail(dot(w, "start"), std::to_string(out.start) + ": an agent's first clip starts at frame 0");
    if (before && out.start <= before->start)
        fail(dot(w, "start"), std::to_string(out.start) + ": clips in time order, the one before starts at frame " +
                                  std::to_string(before->start));
    const json& p = tuple(need(c, "place", w), 4, dot(w, "place"), "[x, y, theta, t0]");
    const std::string wp = dot(w, "place");
    out.place = {coordinate(p[0], at(wp, 0)), coordinate(p[1], at(wp, 1)), finite(p[2], at(wp, 2)),
                 finite(p[3], at(wp, 3))};
    check_time(out.place.t0, out.start, r.dt, 1e-9, at(wp, 3));
    out.fallback = boolean(need(c, "fallback", w), dot(w, "fallback"));
    out.commit = integer(need(c, "commit", w), dot(w, "commit"), -1, kNoLimit);
    if (before && out.commit < before->commit)
        fail(dot(w, "commit"), std::to_string(out.commit) + ": commits in order, the clip before's is " +
                                   std::to_string(before->commit));
    return out;
}

// A goal agent's goals ("goal": [x, y] or "goals": [[x, y], ...], not both) and what it does at the last.
void goals_of(const json& t, const std::string& w, AgentTrack& track) {
    if (t.contains("goal") && t.contains("goals")) fail(w, "\"goal\" or \"goals\", not both");
    const auto point = [&](const json& v, const std::string& place) {
        const json& g = tuple(v, 2, place, "[x, y]");
        track.goals.push_back({coordinate(g[0], at(place, 0)), coordinate(g[1], at(place, 1))});
    };
    if (t.contains("goal")) point(t["goal"], dot(w, "goal"));
    if (t.contains("goals")) {
        const json& goals = array(t["goals"], dot(w, "goals"), "an array of [x, y]");
        if (goals.empty()) fail(dot(w, "goals"), "at least one goal");
        for (std::size_t k = 0; k < goals.size(); ++k) point(goals[k], at(dot(w, "goals"), k));
    }
    if (!t.contains("at_goal")) return;
    const json& v = t["at_goal"];
    const auto at_goal = v.is_string() ? at_goal_of(v.get<std::string>()) : std::nullopt;
    if (!at_goal) fail(dot(w, "at_goal"), "expected \"stay\" or \"leave\"");
    if (track.goals.empty()) fail(dot(w, "at_goal"), "an agent without a goal has none");
    track.at_goal = *at_goal;
}

// An agent: its goals, its clips, and one disk [t, x, y, r] per frame it is in the run, t = k * dt, r >= 0.
AgentTrack track_of(const json& t, const Record& r, const std::string& w) {
    AgentTrack track;
    if (!t.is_object()) fail(w, "expected an object");
    goals_of(t, w, track);
    const json& clips = array(need(t, "clips", w), dot(w, "clips"), "an array of clips");
    if (clips.empty()) fail(dot(w, "clips"), "an agent plays at least one clip");
    for (std::size_t k = 0; k < clips.size(); ++k)
        track.clips.push_back(
            placed_clip_of(clips[k], r, k ? &track.clips.back() : nullptr, at(dot(w, "clips"), k)));
    if (t.contains("left_frame")) track.left_frame = integer(t["left_frame"], dot(w, "left_frame"), 1, r.frames - 1);
    if (track.left_frame && track.at_goal != AtGoal::Leave) fail(dot(w, "left_frame"), "only an agent that leaves has one");
    const std::int64_t frames = track.left_frame.value_or(r.frames);
    const json& samples = array(need(t, "samples", w), dot(w, "samples"), "an array of [t, x, y, r]");
    if (std::int64_t(samples.size()) != frames)
        fail(dot(w, "samples"), std::to_string(samples.size()) + " samples, expected one per frame (" +
                                    std::to_string(frames) + (track.left_frame ? ", until it left)" : ")"));
    track.samples.reserve(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const std::string place = at(dot(w, "samples"), k);
        const json& s = tuple(samples[k], 4, place, "[t, x, y, r]");
        const std::array<double, 4> d{finite(s[0], at(place, 0)), coordinate(s[1], at(place, 1)),
                                      coordinate(s[2], at(place, 2)), radius(s[3], at(place, 3))};
        check_time(d[0], std::int64_t(k), r.dt, 1e-9, at(place, 0));
        track.samples.push_back(d);
    }
    return track;
}

// Escape clips [clip, frame, x, y, theta]: graph clip ids from frame >= 0 on, placed at finite positions.
std::vector<FramedClip> escape_of(const json& escape, double dt, const std::string& w) {
    std::vector<FramedClip> out;
    for (std::size_t k = 0; k < array(escape, w, "an array of [clip, frame, x, y, theta]").size(); ++k) {
        const std::string place = at(w, k);
        const json& e = tuple(escape[k], 5, place, "[clip, frame, x, y, theta]");
        const int clip = index(e[0], at(place, 0), 0, kNoLimit);
        const std::int64_t frame = integer(e[1], at(place, 1), 0, kNoLimit);
        out.push_back({clip,
                       frame,
                       {coordinate(e[2], at(place, 2)), coordinate(e[3], at(place, 3)), finite(e[4], at(place, 4)),
                        double(frame) * dt}});
    }
    return out;
}

// Held ground [x, y, r, frame]: a finite disk, r >= 0, from frame >= 0 on.
HeldGround hold_of(const json& h, const std::string& w) {
    const json& v = tuple(h, 4, w, "[x, y, r, frame]");
    return {{coordinate(v[0], at(w, 0)), coordinate(v[1], at(w, 1)), radius(v[2], at(w, 2))},
            integer(v[3], at(w, 3), 0, kNoLimit)};
}

void plan_of(const json& c, ChoicePoint& cp, const Record& r, const std::string& w) {
    if (!c.contains("plan")) return;
    const std::string wp = dot(w, "plan");
    const json& plan = c["plan"];
    cp.escape = escape_of(need(plan, "escape", wp), r.dt, dot(wp, "escape"));
    if (plan.contains("intended")) cp.intended = escape_of(plan["intended"], r.dt, dot(wp, "intended"));
    if (plan.contains("hold")) {
        const HeldGround h = hold_of(plan["hold"], dot(wp, "hold"));
        cp.holds = true;
        cp.hold = h.disk;
        cp.hold_frame = h.frame;
    }
    if (!plan.contains("reroutes")) return;
    const json& reroutes = array(plan["reroutes"], dot(wp, "reroutes"), "an array");
    for (std::size_t k = 0; k < reroutes.size(); ++k) {
        const std::string place = at(dot(wp, "reroutes"), k);
        const json& j = reroutes[k];
        const int agent = index(need(j, "agent", place), dot(place, "agent"), 0, std::int64_t(r.tracks.size()) - 1);
        const HeldGround h = hold_of(need(j, "hold", place), dot(place, "hold"));
        cp.reroutes.push_back(
            {agent, escape_of(need(j, "escape", place), r.dt, dot(place, "escape")), h.disk, h.frame});
    }
}

// A query [agent, commit, piece, mine, hit]: against a solid (agent -1, commit the solid's index: the
// obstacles, then the four walls when walled), the ground an agent started on (commit -1, piece -1), or a
// piece of an earlier choice point's plan; mine >= -1; hit 0 or 1.
CandidateQuery query_of(const json& q, const Record& r, const std::string& w) {
    const json& v = tuple(q, 5, w, "[agent, commit, piece, mine, hit]");
    const CandidateQuery cq{index(v[0], at(w, 0), -1, std::int64_t(r.tracks.size()) - 1),
                            index(v[1], at(w, 1), -1, kNoLimit), index(v[2], at(w, 2), -1, kNoLimit),
                            index(v[3], at(w, 3), -1, kNoLimit), index(v[4], at(w, 4), 0, 1) != 0};
    if (cq.agent == -1) {
        const std::size_t solids = r.world.obstacles.size() + (r.world.walls ? 4 : 0);
        if (cq.piece != 0) fail(at(w, 2), "a wall or an obstacle (agent -1) is piece 0");
        if (cq.commit < 0 || std::size_t(cq.commit) >= solids)
            fail(at(w, 1), std::to_string(cq.commit) + ": no such wall or obstacle (" + std::to_string(solids) + ")");
        return cq;
    }
    const bool start = cq.commit == -1 && cq.piece == -1;  // the ground the agent started on
    if (!start && (cq.commit < 0 || std::size_t(cq.commit) >= r.choices.size()))  // queries name earlier ones only
        fail(at(w, 1), std::to_string(cq.commit) + ": names no earlier choice point (" +
                           std::to_string(r.choices.size()) + " before this one)");
    return cq;
}

Candidate candidate_of(const json& k, const Record& r, const std::string& w) {
    Candidate cand;
    cand.clip = index(need(k, "clip", w), dot(w, "clip"), 0, kNoLimit);
    cand.outside = boolean(need(k, "outside", w), dot(w, "outside"));
    cand.queries = index(need(k, "queries", w), dot(w, "queries"), 0, kNoLimit);
    cand.hits = index(need(k, "hits", w), dot(w, "hits"), 0, cand.queries);
    const json& against = array(need(k, "against", w), dot(w, "against"), "an array of queries");
    if (against.size() > std::size_t(cand.queries))
        fail(dot(w, "against"), std::to_string(against.size()) + " queries listed, \"queries\" says " +
                                    std::to_string(cand.queries));
    for (std::size_t i = 0; i < against.size(); ++i)
        cand.against.push_back(query_of(against[i], r, at(dot(w, "against"), i)));
    cand.crowded = k.contains("crowded") ? boolean(k["crowded"], dot(w, "crowded")) : false;
    return cand;
}

ChoicePoint choice_of(const json& c, const Record& r, const std::string& w) {
    ChoicePoint cp;
    cp.agent = index(need(c, "agent", w), dot(w, "agent"), 0, std::int64_t(r.tracks.size()) - 1);
    cp.frame = integer(need(c, "frame", w), dot(w, "frame"), 0, r.frames - 1);
    if (c.contains("t")) check_time(finite(c["t"], dot(w, "t")), cp.frame, r.dt, 1e-8, dot(w, "t"));
    cp.taken = index(need(c, "taken", w), dot(w, "taken"), 0, kNoLimit);
    cp.fallback = boolean(need(c, "fallback", w), dot(w, "fallback"));
    cp.outcome = cp.fallback ? "fallback" : "candidate";
    if (c.contains("outcome")) {
        cp.outcome = text(c["outcome"], dot(w, "outcome"));
        static const char* const kOutcomes[] = {"candidate", "escape", "arrived", "fallback", "right of way"};
        if (std::find(std::begin(kOutcomes), std::end(kOutcomes), cp.outcome) == std::end(kOutcomes))
            fail(dot(w, "outcome"), "expected candidate, escape, arrived, fallback or right of way");
    }
    cp.queries = counter(need(c, "queries", w), dot(w, "queries"));
    cp.tests2d = counter(need(c, "tests2d", w), dot(w, "tests2d"));
    cp.tests3d = counter(need(c, "tests3d", w), dot(w, "tests3d"));
    cp.samples = counter(need(c, "samples", w), dot(w, "samples"));
    cp.pruned = counter(need(c, "pruned", w), dot(w, "pruned"));
    plan_of(c, cp, r, w);
    const json& cands = array(need(c, "candidates", w), dot(w, "candidates"), "an array of candidates");
    for (std::size_t k = 0; k < cands.size(); ++k)
        cp.candidates.push_back(candidate_of(cands[k], r, at(dot(w, "candidates"), k)));
    return cp;
}

Record record_of(const json& j) {
    check_header(j);
    Record r;
    r.graph = text(need(j, "graph", ""), "graph");
    r.dt = finite(need(j, "dt", ""), "dt");
    if (!(r.dt > 0)) fail("dt", num(r.dt) + ": must be positive (seconds)");
    if (r.dt < 1 / kMaxGraphFps || r.dt > 1 / kMinGraphFps)  // a frame of its graph
        fail("dt", num(r.dt) + ": expected " + num(1 / kMaxGraphFps) + " to " + num(1 / kMinGraphFps) + " s");
    r.frames = integer(need(j, "frames", ""), "frames", 1, kNoLimit);
    r.world = world_of(j);
    r.seed = counter(need(j, "seed", ""), "seed");
    r.tree = text(need(j, "tree", ""), "tree");
    r.select = text(need(j, "select", ""), "select");
    if (j.contains("scenario")) r.scenario = text(j["scenario"], "scenario");
    for (const char* key : {"summary", "metrics"})
        if (j.contains(key) && !j[key].is_object()) fail(key, "expected an object");
    const json& tracks = array(need(j, "tracks", ""), "tracks", "an array of agents");
    if (tracks.empty()) fail("tracks", "a record has at least one agent");
    if (j.contains("agents") && integer(j["agents"], "agents", 0, kNoLimit) != std::int64_t(tracks.size()))
        fail("agents", std::to_string(j["agents"].get<std::int64_t>()) + ", the record has " +
                           std::to_string(tracks.size()) + " tracks");
    r.tracks.reserve(tracks.size());
    for (std::size_t a = 0; a < tracks.size(); ++a) r.tracks.push_back(track_of(tracks[a], r, at("tracks", a)));
    const json& choices = array(need(j, "choices", ""), "choices", "an array of choice points");
    r.choices.reserve(choices.size());
    for (std::size_t k = 0; k < choices.size(); ++k) r.choices.push_back(choice_of(choices[k], r, at("choices", k)));
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (std::size_t k = 0; k < r.tracks[a].clips.size(); ++k)
            if (r.tracks[a].clips[k].commit >= std::int64_t(r.choices.size()))
                fail(at(at("tracks", a) + ".clips", k) + ".commit",
                     std::to_string(r.tracks[a].clips[k].commit) + ": the record has " +
                         std::to_string(r.choices.size()) + " choice points");
    return r;
}

}  // namespace

std::string record_to_text(const Record& r, const std::string& summary_json, const std::string& metrics_json) {
    J j;
    j["format"] = "mobb crowd record";
    j["version"] = 2;
    j["graph"] = r.graph;
    j["dt"] = r.dt;
    j["frames"] = r.frames;
    j["agents"] = r.tracks.size();
    j["seed"] = r.seed;
    j["tree"] = r.tree;
    j["select"] = r.select;
    if (!r.scenario.empty()) j["scenario"] = r.scenario;
    j["world"] = world_json(r.world);
    j["walls"] = r.world.walls;
    j["obstacles"] = obstacles_json(r.world);
    j["summary"] = summary_json.empty() ? J::object() : J::parse(summary_json);
    if (!metrics_json.empty()) j["metrics"] = J::parse(metrics_json);
    J tracks = J::array();
    for (const AgentTrack& t : r.tracks) tracks.push_back(track_json(t));
    j["tracks"] = tracks;
    J choices = J::array();
    for (const ChoicePoint& c : r.choices) choices.push_back(choice_json(c, r.dt));
    j["choices"] = choices;
    return util::readable_json(j);
}

Record load_record(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file + ": cannot open");
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw std::runtime_error(file + ": not valid JSON");
    try {
        return record_of(j);
    } catch (const Bad& e) {
        throw std::runtime_error(file + ": " + e.what());
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file + ": " + e.what());
    } catch (const std::out_of_range& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

void check_graph_clips(const Record& r, std::size_t clips) {
    const auto check = [&](int clip, const std::string& place) {
        if (clip < 0 || std::size_t(clip) >= clips)
            throw std::runtime_error(place + ": clip " + std::to_string(clip) + " is not in the graph " + r.graph +
                                     " (" + std::to_string(clips) + " clips)");
    };
    const auto escape = [&](const std::vector<FramedClip>& e, const std::string& place) {
        for (std::size_t k = 0; k < e.size(); ++k) check(e[k].clip, at(place, k) + "[0]");
    };
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (std::size_t k = 0; k < r.tracks[a].clips.size(); ++k)
            check(r.tracks[a].clips[k].clip, at(at("tracks", a) + ".clips", k) + ".clip");
    for (std::size_t c = 0; c < r.choices.size(); ++c) {
        const ChoicePoint& cp = r.choices[c];
        const std::string w = at("choices", c);
        check(cp.taken, w + ".taken");
        for (std::size_t k = 0; k < cp.candidates.size(); ++k)
            check(cp.candidates[k].clip, at(w + ".candidates", k) + ".clip");
        escape(cp.escape, w + ".plan.escape");
        escape(cp.intended, w + ".plan.intended");
        for (std::size_t k = 0; k < cp.reroutes.size(); ++k)
            escape(cp.reroutes[k].escape, at(w + ".plan.reroutes", k) + ".escape");
    }
}

}  // namespace mobb::crowd
