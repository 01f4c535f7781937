// Reading a crowd record from JSON: every field checked against what it means (record.h).
#include "mobb/crowd/record/record.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "mobb/crowd/graph/motion_graph.h"
#include "record/record_json.h"

namespace mobb::crowd {

namespace {

// Reading a record: every field checked against what it means. A problem throws Bad "PLACE: message"
// (PLACE like tracks[2].samples[7][3]); load_record puts the file in front.
using json = nlohmann::ordered_json;  // ordered: the summary and metrics keep their order

using Bad = FieldError;

[[noreturn]] void fail(const std::string& place, const std::string& message) { throw Bad(place + ": " + message); }

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
    check_coordinate(x, [&] { return place; });
    return x;
}

double radius(const json& v, const std::string& place) {
    const double x = finite(v, place);
    check_radius(x, [&] { return place; });
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
    check_frame_time(t, frame, dt, slack, [&] { return place; });
}

void check_header(const json& j) {
    if (j.contains("format") && j["format"] != "mobb crowd record") fail("format", "expected \"mobb crowd record\"");
    if (j.contains("version")) integer(j["version"], "version", 1, kRecordVersion);
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
        const std::string place = element_place("obstacles", k);
        const json& poly = array(obstacles[k], place, "a polygon [[x, y], ...]");
        if (poly.size() < 2) fail(place, "a polygon has two or more vertices");
        Polygon p;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const json& q = tuple(poly[i], 2, element_place(place, i), "[x, y]");
            p.vertices.push_back({coordinate(q[0], element_place(element_place(place, i), 0)),
                                  coordinate(q[1], element_place(element_place(place, i), 1))});
        }
        w.obstacles.push_back(std::move(p));
    }
    return w;
}

// A track's clips: graph clip ids, the first from frame 0, then starting in time order inside the run,
// each placed at its start time (t0 = start * dt), taken by choice points in order ("choice", -1: none,
// the agent's first clip; the choice points' count is checked once they are read).
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
    out.place = {coordinate(p[0], element_place(wp, 0)), coordinate(p[1], element_place(wp, 1)),
                 finite(p[2], element_place(wp, 2)), finite(p[3], element_place(wp, 3))};
    check_time(out.place.t0, out.start, r.dt, 1e-9, element_place(wp, 3));
    out.fallback = boolean(need(c, "fallback", w), dot(w, "fallback"));
    out.choice = integer(need(c, "choice", w), dot(w, "choice"), -1, kNoLimit);
    if (before && out.choice < before->choice)
        fail(dot(w, "choice"), std::to_string(out.choice) + ": choice points in order, the clip before's is " +
                                   std::to_string(before->choice));
    return out;
}

// A goal agent's goals ("goal": [x, y] or "goals": [[x, y], ...], not both) and what it does at the last.
void goals_of(const json& t, const std::string& w, AgentTrack& track) {
    if (t.contains("goal") && t.contains("goals")) fail(w, "\"goal\" or \"goals\", not both");
    const auto point = [&](const json& v, const std::string& place) {
        const json& g = tuple(v, 2, place, "[x, y]");
        track.goals.push_back({coordinate(g[0], element_place(place, 0)), coordinate(g[1], element_place(place, 1))});
    };
    if (t.contains("goal")) point(t["goal"], dot(w, "goal"));
    if (t.contains("goals")) {
        const json& goals = array(t["goals"], dot(w, "goals"), "an array of [x, y]");
        if (goals.empty()) fail(dot(w, "goals"), "at least one goal");
        for (std::size_t k = 0; k < goals.size(); ++k) point(goals[k], element_place(dot(w, "goals"), k));
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
            placed_clip_of(clips[k], r, k ? &track.clips.back() : nullptr, element_place(dot(w, "clips"), k)));
    if (t.contains("left_frame")) track.left_frame = integer(t["left_frame"], dot(w, "left_frame"), 1, r.frames - 1);
    if (track.left_frame && track.at_goal != AtGoal::Leave)
        fail(dot(w, "left_frame"), "only an agent that leaves has one");
    const std::int64_t frames = track.left_frame.value_or(r.frames);
    const json& samples = array(need(t, "samples", w), dot(w, "samples"), "an array of [t, x, y, r]");
    if (std::int64_t(samples.size()) != frames)
        fail(dot(w, "samples"), std::to_string(samples.size()) + " samples, expected one per frame (" +
                                    std::to_string(frames) + (track.left_frame ? ", until it left)" : ")"));
    track.samples.reserve(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const std::string place = element_place(dot(w, "samples"), k);
        const json& s = tuple(samples[k], 4, place, "[t, x, y, r]");
        const std::array<double, 4> d{finite(s[0], element_place(place, 0)), coordinate(s[1], element_place(place, 1)),
                                      coordinate(s[2], element_place(place, 2)), radius(s[3], element_place(place, 3))};
        check_time(d[0], std::int64_t(k), r.dt, 1e-9, element_place(place, 0));
        track.samples.push_back(d);
    }
    return track;
}

// Escape clips [clip, frame, x, y, theta]: graph clip ids from frame >= 0 on, placed at finite positions.
std::vector<FramedClip> escape_of(const json& escape, double dt, const std::string& w) {
    std::vector<FramedClip> out;
    for (std::size_t k = 0; k < array(escape, w, "an array of [clip, frame, x, y, theta]").size(); ++k) {
        const std::string place = element_place(w, k);
        const json& e = tuple(escape[k], 5, place, "[clip, frame, x, y, theta]");
        const int clip = index(e[0], element_place(place, 0), 0, kNoLimit);
        const std::int64_t frame = integer(e[1], element_place(place, 1), 0, kNoLimit);
        out.push_back({clip,
                       frame,
                       {coordinate(e[2], element_place(place, 2)), coordinate(e[3], element_place(place, 3)),
                        finite(e[4], element_place(place, 4)), double(frame) * dt}});
    }
    return out;
}

// Held ground [x, y, r, frame]: a finite disk, r >= 0, from frame >= 0 on.
HeldGround hold_of(const json& h, const std::string& w) {
    const json& v = tuple(h, 4, w, "[x, y, r, frame]");
    return {{coordinate(v[0], element_place(w, 0)), coordinate(v[1], element_place(w, 1)),
             radius(v[2], element_place(w, 2))},
            integer(v[3], element_place(w, 3), 0, kNoLimit)};
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
        const std::string place = element_place(dot(wp, "reroutes"), k);
        const json& j = reroutes[k];
        const int agent = index(need(j, "agent", place), dot(place, "agent"), 0, std::int64_t(r.tracks.size()) - 1);
        const HeldGround h = hold_of(need(j, "hold", place), dot(place, "hold"));
        cp.reroutes.push_back(
            {agent, escape_of(need(j, "escape", place), r.dt, dot(place, "escape")), h.disk, h.frame});
    }
}

// A query [agent, index, piece, mine, hit]: against a solid (agent -1, index the solid's: the obstacles,
// then the four walls when walled), the ground an agent started on (index -1, piece -1), or a piece of
// the plan of an earlier choice point (index its place in "choices"); mine >= -1; hit 0 or 1.
// `earlier`: the choice points before the one asking.
CandidateQuery query_of(const json& q, const Record& r, std::size_t earlier, const std::string& w) {
    const json& v = tuple(q, 5, w, "[agent, index, piece, mine, hit]");
    CandidateQuery cq;
    cq.agent = index(v[0], element_place(w, 0), -1, std::int64_t(r.tracks.size()) - 1);
    const int i = index(v[1], element_place(w, 1), -1, kNoLimit);
    cq.piece = index(v[2], element_place(w, 2), -1, kNoLimit);
    cq.mine = index(v[3], element_place(w, 3), -1, kNoLimit);
    cq.hit = index(v[4], element_place(w, 4), 0, 1) != 0;
    if (cq.agent == -1) {
        const std::size_t solids = r.world.obstacles.size() + (r.world.walls ? 4 : 0);
        if (cq.piece != 0) fail(element_place(w, 2), "a wall or an obstacle (agent -1) is piece 0");
        if (i < 0 || std::size_t(i) >= solids)
            fail(element_place(w, 1),
                 std::to_string(i) + ": no such wall or obstacle (" + std::to_string(solids) + ")");
        cq.solid = i;
        return cq;
    }
    const bool start = i == -1 && cq.piece == -1;        // the ground the agent started on
    if (!start && (i < 0 || std::size_t(i) >= earlier))  // queries name earlier ones only
        fail(element_place(w, 1),
             std::to_string(i) + ": names no earlier choice point (" + std::to_string(earlier) + " before this one)");
    cq.choice = i;
    return cq;
}

Candidate candidate_of(const json& k, const Record& r, std::size_t earlier, const std::string& w) {
    Candidate cand;
    cand.clip = index(need(k, "clip", w), dot(w, "clip"), 0, kNoLimit);
    cand.leaves_world = boolean(need(k, "leaves_world", w), dot(w, "leaves_world"));
    cand.meets_solid = boolean(need(k, "meets_solid", w), dot(w, "meets_solid"));
    cand.queries = index(need(k, "queries", w), dot(w, "queries"), 0, kNoLimit);
    cand.hits = index(need(k, "hits", w), dot(w, "hits"), 0, cand.queries);
    const json& against = array(need(k, "against", w), dot(w, "against"), "an array of queries");
    if (against.size() > std::size_t(cand.queries))
        fail(dot(w, "against"),
             std::to_string(against.size()) + " queries listed, \"queries\" says " + std::to_string(cand.queries));
    for (std::size_t i = 0; i < against.size(); ++i)
        cand.against.push_back(query_of(against[i], r, earlier, element_place(dot(w, "against"), i)));
    cand.crowded = k.contains("crowded") ? boolean(k["crowded"], dot(w, "crowded")) : false;
    return cand;
}

// Choice point `row` (`row` before it).
ChoicePoint choice_of(const json& c, const Record& r, std::size_t row) {
    const std::string w = element_place("choices", row);
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
        cp.candidates.push_back(candidate_of(cands[k], r, row, element_place(dot(w, "candidates"), k)));
    return cp;
}

// The header: everything before the tracks.
Record header_of(const json& j) {
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
    if (r.select == "avoid") r.select = "wander";  // its name before issue 44, read in today's
    if (j.contains("scenario")) r.scenario = text(j["scenario"], "scenario");
    for (const char* key : {"summary", "metrics"})
        if (j.contains(key) && !j[key].is_object()) fail(key, "expected an object");
    return r;
}

Record record_of(const json& j) {
    Record r = header_of(j);
    const json& tracks = array(need(j, "tracks", ""), "tracks", "an array of agents");
    if (tracks.empty()) fail("tracks", "a record has at least one agent");
    if (j.contains("agents") && integer(j["agents"], "agents", 0, kNoLimit) != std::int64_t(tracks.size()))
        fail("agents", std::to_string(j["agents"].get<std::int64_t>()) + ", the record has " +
                           std::to_string(tracks.size()) + " tracks");
    r.tracks.reserve(tracks.size());
    for (std::size_t a = 0; a < tracks.size(); ++a)
        r.tracks.push_back(track_of(tracks[a], r, element_place("tracks", a)));
    const json& choices = array(need(j, "choices", ""), "choices", "an array of choice points");
    r.choices.reserve(choices.size());
    for (std::size_t k = 0; k < choices.size(); ++k) r.choices.push_back(choice_of(choices[k], r, k));
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (std::size_t k = 0; k < r.tracks[a].clips.size(); ++k)
            if (r.tracks[a].clips[k].choice >= std::int64_t(r.choices.size()))
                fail(element_place(element_place("tracks", a) + ".clips", k) + ".choice",
                     std::to_string(r.tracks[a].clips[k].choice) + ": the record has " +
                         std::to_string(r.choices.size()) + " choice points");
    return r;
}

// A record of version 1 or 2 in this version's names: a clip's "commit" is its "choice"; a candidate's
// one flag "outside" meant leaving the world in random mode (which queries no solids: meets_solid false)
// and meeting a wall or an obstacle otherwise.
json upgraded(const json& j) {
    json out = j;
    out["version"] = kRecordVersion;
    const bool random = j.contains("select") && j["select"] == "random";
    const auto rename = [](json& o, const char* from, const char* to) {
        if (!o.is_object() || !o.contains(from)) return;
        json v = std::move(o[from]);  // moved out first: inserting `to` may move the object's members
        o.erase(from);
        o[to] = std::move(v);
    };
    const auto each = [](json& parent, const char* key, const auto& f) {
        if (parent.is_object() && parent.contains(key) && parent[key].is_array())
            for (json& x : parent[key]) f(x);
    };
    each(out, "tracks", [&](json& t) { each(t, "clips", [&](json& c) { rename(c, "commit", "choice"); }); });
    each(out, "choices", [&](json& c) {
        each(c, "candidates", [&](json& k) {
            if (!k.is_object() || !k.contains("outside")) return;
            k[random ? "meets_solid" : "leaves_world"] = false;
            rename(k, "outside", random ? "leaves_world" : "meets_solid");
        });
    });
    return out;
}

bool older(const json& j) {
    const auto it = j.find("version");
    return it != j.end() && it->is_number_integer() && it->get<std::int64_t>() >= 1 &&
           it->get<std::int64_t>() < kRecordVersion;
}

}  // namespace

Record record_from_json(const nlohmann::ordered_json& j, const std::string& file) {
    if (!j.is_object()) throw std::runtime_error(file + ": not valid JSON");
    try {
        return older(j) ? record_of(upgraded(j)) : record_of(j);
    } catch (const Bad& e) {
        throw std::runtime_error(file + ": " + e.what());
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file + ": " + e.what());
    } catch (const std::out_of_range& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

Record record_header_from_json(const nlohmann::ordered_json& j, const std::string& file) {
    try {
        return header_of(j);
    } catch (const Bad& e) {
        throw std::runtime_error(file + ": " + e.what());
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

ChoicePoint choice_from_json(const nlohmann::ordered_json& c, const Record& header, std::size_t row,
                             const std::string& file) {
    try {
        return choice_of(c, header, row);
    } catch (const Bad& e) {
        throw std::runtime_error(file + ": " + e.what());
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

void check_finite(double x, const Place& place) {
    if (!std::isfinite(x)) fail(place(), "expected a finite number");
}

void check_coordinate(double x, const Place& place) {
    check_finite(x, place);
    if (std::abs(x) > kFar) fail(place(), num(x) + ": farther than " + num(kFar) + " m from the origin");
}

void check_radius(double r, const Place& place) {
    check_finite(r, place);
    if (r < 0) fail(place(), num(r) + ": a radius is not negative");
    if (r > kMaxRadius) fail(place(), num(r) + ": a character's radius is at most " + num(kMaxRadius) + " m");
}

bool disk_ok(const std::array<double, 4>& d, std::int64_t frame, double dt) {
    const double want = double(frame) * dt;
    return std::abs(d[0] - want) <= 1e-9 * (1 + std::abs(want)) && std::abs(d[1]) <= kFar && std::abs(d[2]) <= kFar &&
           d[3] >= 0 && d[3] <= kMaxRadius;  // false for NaN
}

void check_frame_time(double t, std::int64_t frame, double dt, double slack, const Place& place) {
    const double want = double(frame) * dt;
    if (!(std::abs(t - want) <= slack * (1 + std::abs(want))))
        fail(place(), num(t) + " s, frame " + std::to_string(frame) + " starts at " + num(want) + " s");
}

std::string stored_summary(const nlohmann::ordered_json& j) {
    const json& s = j["summary"];
    if (!older(j) || !s.is_object()) return s.dump();
    json out = json::object();  // in the same order
    for (const auto& [key, value] : s.items())
        out[key == "fallbacks_outside_world" ? "fallbacks_meeting_solids" : key] = value;
    return out.dump();
}

RecordFile read_json_record(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file + ": cannot open");
    std::error_code size_error;
    const std::uintmax_t bytes = std::filesystem::file_size(file, size_error);
    if (!size_error) check_json_record_read(file, bytes);  // before the document takes the memory
    const json j = json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw std::runtime_error(file + ": not valid JSON");
    RecordFile out;
    out.record = record_from_json(j, file);
    if (j.contains("summary")) out.summary_json = stored_summary(j);
    if (j.contains("metrics")) out.metrics_json = j["metrics"].dump();
    return out;
}

namespace {

void check_clip(int clip, std::size_t clips, const std::string& graph, const std::string& place) {
    if (clip < 0 || std::size_t(clip) >= clips)
        throw std::runtime_error(place + ": clip " + std::to_string(clip) + " is not in the graph " + graph + " (" +
                                 std::to_string(clips) + " clips)");
}

}  // namespace

void check_choice_clips(const ChoicePoint& cp, std::size_t row, std::size_t clips, const std::string& graph) {
    const auto escape = [&](const std::vector<FramedClip>& e, const std::string& place) {
        for (std::size_t k = 0; k < e.size(); ++k) check_clip(e[k].clip, clips, graph, element_place(place, k) + "[0]");
    };
    const std::string w = element_place("choices", row);
    check_clip(cp.taken, clips, graph, w + ".taken");
    for (std::size_t k = 0; k < cp.candidates.size(); ++k)
        check_clip(cp.candidates[k].clip, clips, graph, element_place(w + ".candidates", k) + ".clip");
    escape(cp.escape, w + ".plan.escape");
    escape(cp.intended, w + ".plan.intended");
    for (std::size_t k = 0; k < cp.reroutes.size(); ++k)
        escape(cp.reroutes[k].escape, element_place(w + ".plan.reroutes", k) + ".escape");
}

void check_graph_clips(const Record& r, std::size_t clips) {
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (std::size_t k = 0; k < r.tracks[a].clips.size(); ++k)
            check_clip(r.tracks[a].clips[k].clip, clips, r.graph,
                       element_place(element_place("tracks", a) + ".clips", k) + ".clip");
    for (std::size_t c = 0; c < r.choices.size(); ++c) check_choice_clips(r.choices[c], c, clips, r.graph);
}

std::string element_place(const std::string& place, std::size_t k) { return place + "[" + std::to_string(k) + "]"; }

}  // namespace mobb::crowd
