// Reading a crowd record from HDF5 (the layout in docs/formats.md): the file's datasets are read block by
// block into the JSON layout, which the JSON reader then checks field by field, so both kinds of file
// hold a record to the same rules and name a bad field the same way.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <string>

#include "mobb/util/json_text.h"
#include "record/frame_blocks.h"
#include "record/h5.h"
#include "record/record_h5_read.h"
#include "record/record_json.h"

namespace mobb::crowd {

namespace {

using h5read::Held;
using J = nlohmann::ordered_json;
using I = std::vector<std::int64_t>;
using D = std::vector<double>;

template <class T>
T one(hid_t f, const char* name) {
    const auto v = h5::read_numbers<T>(f, name);
    if (!v || v->size() != 1) throw h5::Error(std::string("attribute ") + name + ": expected one number");
    return v->front();
}

std::string text(hid_t f, const char* name) {
    const auto v = h5::read_text(f, name);
    if (!v) throw h5::Error(std::string("attribute ") + name + ": missing");
    return *v;
}

J object(hid_t f, const char* name) {
    const auto v = h5::read_text(f, name);
    if (!v) return nullptr;
    J j = J::parse(*v, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        throw h5::Error(std::string("attribute ") + name + ": expected a JSON object");
    return j;
}

template <class T>
std::vector<T> rows(hid_t f, const std::string& path, const Held& held, std::vector<hsize_t> inner = {}) {
    auto v = h5::read_rows<T>(f, path, inner, held.limit(path));
    if (!v) throw h5::Error(path + ": missing");
    return std::move(*v);
}

// The rows of a nested table to take: all `n` of a finished file; of an incomplete one, those whose owner
// is one of the `owners` taken (the rows come in their owners' order).
std::size_t taken(const std::vector<std::int64_t>& owner, std::size_t owners, const Held& held, std::size_t n) {
    if (held.complete) return n;
    std::size_t k = 0;
    while (k < n && owner[k] >= 0 && std::size_t(owner[k]) < owners) ++k;
    return k;
}

// A table's columns, all of one length `n` (the first column's): the rows of the table.
std::size_t same_rows(const std::string& group, std::initializer_list<std::pair<const char*, std::size_t>> sizes) {
    const std::size_t n = sizes.begin()->second;
    for (const auto& [name, size] : sizes)
        if (size != n) {
            std::string what = group;
            what.append("/").append(name).append(": ").append(std::to_string(size)).append(" rows, ");
            what.append(group).append(" has ").append(std::to_string(n));
            throw h5::Error(what);
        }
    return n;
}

// The owner row of row k of a nested table, checked to be one of `owners`.
std::size_t owner(const I& column, std::size_t k, std::size_t owners, const std::string& path) {
    if (column[k] < 0 || std::size_t(column[k]) >= owners)
        throw h5::Error(path + " row " + std::to_string(k) + ": " + std::to_string(column[k]) + ", there are " +
                        std::to_string(owners));
    return std::size_t(column[k]);
}

// The tables in the order of the "written" mark (record_h5_write.cpp).
const char* const kMarked[] = {"/choices",  "/clips",           "/escapes",    "/intended",
                               "/reroutes", "/reroute_escapes", "/candidates", "/queries"};

// An incomplete file's mark: the frames and each table's rows it holds for sure.
Held held_of(hid_t f, std::int64_t planned) {
    Held h;
    h.planned = planned;
    h.frames = planned;
    if (one<std::int64_t>(f, "complete") == 1) return h;
    h.complete = false;
    const auto w = h5::read_numbers<std::int64_t>(f, "written");
    if (!w || w->size() != 1 + std::size(kMarked))
        throw h5::Error("incomplete: the writing stopped before its first mark (attribute written)");
    h.frames = w->front();
    if (h.frames < 1 || h.frames > planned)
        throw h5::Error("incomplete: attribute written: " + std::to_string(h.frames) + " frames, the run has " +
                        std::to_string(planned) + (h.frames < 1 ? " (none written before it stopped)" : ""));
    for (std::size_t k = 0; k < std::size(kMarked); ++k) {
        if ((*w)[k + 1] < 0) throw h5::Error("attribute written: a negative row count");
        h.rows[kMarked[k]] = std::size_t((*w)[k + 1]);
    }
    return h;
}

}  // namespace

J h5read::header(hid_t f, Held& held) {
    const auto complete = h5::read_numbers<std::int64_t>(f, "complete");
    if (complete && complete->size() == 1 && complete->front() != 1 && H5Aexists(f, "written") <= 0)
        throw h5::Error("incomplete: the writing stopped before its first mark (attribute written)");
    if (h5::read_text(f, "format") != "mobb crowd record")
        throw h5::Error("attribute format: expected \"mobb crowd record\"");
    held = held_of(f, one<std::int64_t>(f, "frames"));
    J j;
    j["format"] = "mobb crowd record";
    j["version"] = one<std::int64_t>(f, "version");
    j["graph"] = text(f, "graph");
    j["dt"] = one<double>(f, "dt");
    j["frames"] = held.frames;
    j["agents"] = one<std::int64_t>(f, "agents");
    j["seed"] = one<std::uint64_t>(f, "seed");
    j["tree"] = text(f, "tree");
    j["select"] = text(f, "select");
    if (const auto s = h5::read_text(f, "scenario")) j["scenario"] = *s;
    const auto w = h5::read_numbers<double>(f, "world");
    if (!w || w->size() != 4) throw h5::Error("attribute world: expected [x0, y0, x1, y1]");
    j["world"] = (*w)[0] == 0 && (*w)[1] == 0 ? J{(*w)[2], (*w)[3]} : J{(*w)[0], (*w)[1], (*w)[2], (*w)[3]};
    j["walls"] = one<std::int64_t>(f, "walls") != 0;
    j["summary"] = object(f, "summary");
    if (J m = object(f, "metrics"); !m.is_null()) j["metrics"] = m;
    return j;
}

J h5read::obstacles(hid_t f) {
    const Held all;
    const I polygon = rows<std::int64_t>(f, "/obstacles/polygon", all);
    const D vertex = rows<double>(f, "/obstacles/vertex", all, {2});
    const std::size_t n = same_rows("/obstacles", {{"polygon", polygon.size()}, {"vertex", vertex.size() / 2}});
    J out = J::array();
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t p = owner(polygon, k, out.size() + 1, "/obstacles/polygon");  // in order, from 0
        if (p == out.size()) out.push_back(J::array());
        out[p].push_back({vertex[2 * k], vertex[2 * k + 1]});
    }
    return out;
}

namespace {

// An incomplete file's agents that left: the first frame of NaN in its samples (finish() writes the
// frames they left at).
I left_frames(const D& samples, std::int64_t frames, std::size_t agents) {
    I left(agents, -1);
    for (std::size_t a = 0; a < agents; ++a)
        for (std::int64_t k = 0; k < frames && left[a] < 0; ++k)
            if (std::isnan(samples[(std::size_t(k) * agents + a) * 4])) left[a] = k;
    return left;
}

// `older`: a record of version 2, whose clips name their choice point "commit" (read as the JSON reader's
// upgrade has it).
J tracks(hid_t f, std::int64_t frames, std::size_t agents, const Held& held, bool older) {
    const char* const choice = older ? "commit" : "choice";
    const auto read =
        h5::read_rows<double>(f, "/tracks/samples", {hsize_t(agents), 4}, held.complete ? ~hsize_t(0) : hsize_t(frames),
                              hsize_t(block_frames(agents)));  // an incomplete file: the frames of the mark
    if (!read) throw h5::Error("/tracks/samples: missing");
    const D& samples = *read;
    if (std::int64_t(samples.size() / (4 * std::max<std::size_t>(1, agents))) != frames)
        throw h5::Error("/tracks/samples: " + std::to_string(samples.size() / (4 * agents)) +
                        " frames, the record has " + std::to_string(frames));
    const I left =
        held.complete ? rows<std::int64_t>(f, "/tracks/left_frame", held) : left_frames(samples, frames, agents);
    const I at_goal = rows<std::int64_t>(f, "/tracks/at_goal", held);
    same_rows("/tracks", {{"left_frame", left.size()}, {"at_goal", at_goal.size()}, {"(agents)", agents}});
    J out = J::array();
    for (std::size_t a = 0; a < agents; ++a) {
        J t = J::object();
        if (at_goal[a]) t["at_goal"] = "leave";
        if (left[a] >= 0) t["left_frame"] = left[a];
        t["clips"] = J::array();
        t["samples"] = J::array();
        out.push_back(std::move(t));
    }
    const I goal_agent = rows<std::int64_t>(f, "/goals/agent", held);
    const D goal = rows<double>(f, "/goals/xy", held, {2});
    for (std::size_t k = 0; k < same_rows("/goals", {{"agent", goal_agent.size()}, {"xy", goal.size() / 2}}); ++k)
        out[owner(goal_agent, k, agents, "/goals/agent")]["goals"].push_back({goal[2 * k], goal[2 * k + 1]});
    for (J& t : out)
        if (t.contains("goals") && t["goals"].size() == 1) t["goal"] = t["goals"][0], t.erase("goals");
    const I agent = rows<std::int64_t>(f, "/clips/agent", held), clip = rows<std::int64_t>(f, "/clips/clip", held),
            start = rows<std::int64_t>(f, "/clips/start", held),
            fallback = rows<std::int64_t>(f, "/clips/fallback", held),
            taker = rows<std::int64_t>(f, std::string("/clips/") + choice, held);
    const D place = rows<double>(f, "/clips/place", held, {4});
    const std::size_t n = same_rows("/clips", {{"agent", agent.size()},
                                               {"clip", clip.size()},
                                               {"start", start.size()},
                                               {"fallback", fallback.size()},
                                               {choice, taker.size()},
                                               {"place", place.size() / 4}});
    for (std::size_t k = 0; k < n; ++k)
        if (held.complete || start[k] < frames)  // an incomplete file: the clips of the frames it holds
            out[owner(agent, k, agents, "/clips/agent")]["clips"].push_back(
                {{"clip", clip[k]},
                 {"start", start[k]},
                 {"place", {place[4 * k], place[4 * k + 1], place[4 * k + 2], place[4 * k + 3]}},
                 {"fallback", fallback[k] != 0},
                 {choice, taker[k]}});
    for (std::size_t a = 0; a < agents; ++a) {
        const std::int64_t until = left[a] >= 0 ? std::min(left[a], frames) : frames;
        for (std::int64_t k = 0; k < until; ++k) {
            const double* s = &samples[(std::size_t(k) * agents + a) * 4];
            out[a]["samples"].push_back({s[0], s[1], s[2], s[3]});
        }
    }
    return out;
}

// Clips placed from a frame on, nested by owner: [clip, frame, x, y, theta] rows added to `into(owner)`.
template <class Into>
void framed(hid_t f, const std::string& group, const char* owner_name, std::size_t owners, const Held& held,
            Into into) {
    const I own = rows<std::int64_t>(f, group + "/" + owner_name, held),
            clip = rows<std::int64_t>(f, group + "/clip", held), frame = rows<std::int64_t>(f, group + "/frame", held);
    const D place = rows<double>(f, group + "/place", held, {3});
    const std::size_t n = taken(
        own, owners, held,
        same_rows(
            group,
            {{owner_name, own.size()}, {"clip", clip.size()}, {"frame", frame.size()}, {"place", place.size() / 3}}));
    for (std::size_t k = 0; k < n; ++k)
        into(owner(own, k, owners, group + "/" + owner_name))
            .push_back({clip[k], frame[k], place[3 * k], place[3 * k + 1], place[3 * k + 2]});
}

// A counter as the JSON reader has it (unsigned when not negative; a negative one it refuses).
J count(std::int64_t v) { return v >= 0 ? J(std::uint64_t(v)) : J(v); }

J choices(hid_t f, double dt, const Held& held) {
    static const char* const kNames[] = {"agent",   "frame",   "taken",   "outcome", "fallback",  "queries",
                                         "tests2d", "tests3d", "samples", "pruned",  "hold_frame"};
    std::vector<I> c;
    for (const char* name : kNames) c.push_back(rows<std::int64_t>(f, std::string("/choices/") + name, held));
    const D hold = rows<double>(f, "/choices/hold", held, {3});
    std::size_t n = c[0].size();
    for (std::size_t k = 0; k < c.size(); ++k) same_rows("/choices", {{"agent", n}, {kNames[k], c[k].size()}});
    same_rows("/choices", {{"agent", n}, {"hold", hold.size() / 3}});
    if (!held.complete)  // the choice points of the frames held (they come in frame order)
        n = std::size_t(std::find_if(c[1].begin(), c[1].begin() + std::ptrdiff_t(n),
                                     [&](std::int64_t frame) { return frame >= held.frames; }) -
                        c[1].begin());
    J out = J::array();
    for (std::size_t k = 0; k < n; ++k) {
        if (c[3][k] < 0 || c[3][k] > 4)
            throw h5::Error("/choices/outcome row " + std::to_string(k) + ": expected 0 to 4");
        J plan = {{"escape", J::array()}};
        if (c[10][k] >= 0) plan["hold"] = {hold[3 * k], hold[3 * k + 1], hold[3 * k + 2], c[10][k]};
        out.push_back({{"agent", c[0][k]},
                       {"frame", c[1][k]},
                       {"t", util::rounded(double(c[1][k]) * dt, 9)},
                       {"taken", c[2][k]},
                       {"outcome", h5read::kOutcomes[c[3][k]]},
                       {"fallback", c[4][k] != 0},
                       {"queries", count(c[5][k])},
                       {"tests2d", count(c[6][k])},
                       {"tests3d", count(c[7][k])},
                       {"samples", count(c[8][k])},
                       {"pruned", count(c[9][k])},
                       {"plan", plan},
                       {"candidates", J::array()}});
    }
    framed(f, "/escapes", "choice", n, held, [&](std::size_t k) -> J& { return out[k]["plan"]["escape"]; });
    framed(f, "/intended", "choice", n, held, [&](std::size_t k) -> J& { return out[k]["plan"]["intended"]; });
    const I rc = rows<std::int64_t>(f, "/reroutes/choice", held), ra = rows<std::int64_t>(f, "/reroutes/agent", held),
            rf = rows<std::int64_t>(f, "/reroutes/hold_frame", held);
    const D rh = rows<double>(f, "/reroutes/hold", held, {3});
    const std::size_t nr = taken(
        rc, n, held,
        same_rows("/reroutes",
                  {{"choice", rc.size()}, {"agent", ra.size()}, {"hold_frame", rf.size()}, {"hold", rh.size() / 3}}));
    std::vector<std::pair<std::size_t, std::size_t>> reroute_at;  // (choice, index in its reroutes)
    for (std::size_t k = 0; k < nr; ++k) {
        J& list = out[owner(rc, k, n, "/reroutes/choice")]["plan"]["reroutes"];
        list.push_back(
            {{"agent", ra[k]}, {"escape", J::array()}, {"hold", {rh[3 * k], rh[3 * k + 1], rh[3 * k + 2], rf[k]}}});
        reroute_at.emplace_back(std::size_t(rc[k]), list.size() - 1);
    }
    framed(f, "/reroute_escapes", "reroute", nr, held, [&](std::size_t k) -> J& {
        return out[reroute_at[k].first]["plan"]["reroutes"][reroute_at[k].second]["escape"];
    });
    return out;
}

// The candidates of each choice point, with their queries ("against"). `older`: version 2, one flag
// "outside" for leaves_world and meets_solid, a query's index named "commit" (the JSON reader upgrades).
void candidates(hid_t f, J& choices, const Held& held, bool older) {
    static const std::vector<const char*> kNames = {"choice",  "clip", "leaves_world", "meets_solid",
                                                    "queries", "hits", "crowded"};
    static const std::vector<const char*> kOlder = {"choice", "clip", "outside", "queries", "hits", "crowded"};
    const std::vector<const char*>& names = older ? kOlder : kNames;
    const std::size_t flags = names.size() - 5;  // the flags, from column 2 on
    std::vector<I> c;
    c.reserve(names.size());
    for (const char* name : names) c.push_back(rows<std::int64_t>(f, std::string("/candidates/") + name, held));
    for (std::size_t k = 0; k < c.size(); ++k)
        same_rows("/candidates", {{"choice", c[0].size()}, {names[k], c[k].size()}});
    const char* const kQuery[] = {"candidate", "agent", older ? "commit" : "index", "piece", "mine", "hit"};
    std::vector<I> q;
    for (const char* name : kQuery) q.push_back(rows<std::int64_t>(f, std::string("/queries/") + name, held));
    for (std::size_t k = 0; k < q.size(); ++k)
        same_rows("/queries", {{"candidate", q[0].size()}, {kQuery[k], q[k].size()}});
    const std::size_t nc = taken(c[0], choices.size(), held, c[0].size());
    std::vector<J> against(nc, J::array());
    for (std::size_t k = 0; k < taken(q[0], nc, held, q[0].size()); ++k)
        against[owner(q[0], k, against.size(), "/queries/candidate")].push_back(
            {q[1][k], q[2][k], q[3][k], q[4][k], q[5][k]});
    for (std::size_t k = 0; k < nc; ++k) {
        J& list = choices[owner(c[0], k, choices.size(), "/candidates/choice")]["candidates"];
        J cand = {{"clip", c[1][k]}};
        for (std::size_t i = 2; i < 2 + flags; ++i) cand[names[i]] = c[i][k] != 0;
        cand["queries"] = c[2 + flags][k];
        cand["hits"] = c[3 + flags][k];
        cand["against"] = std::move(against[k]);
        if (c[4 + flags][k]) cand["crowded"] = true;
        list.push_back(std::move(cand));
    }
}

}  // namespace

std::string h5read::note(const std::string& file, const Held& held) {
    if (held.complete) return "";
    return file + ": incomplete (its writing stopped before the end: killed, or a full disk): read up to its " +
           "last mark, frames 0 to " + std::to_string(held.frames - 1) + " (" + std::to_string(held.frames) +
           " of the run's " + std::to_string(held.planned) + ")";
}

RecordFile read_h5_record(const std::string& file) {
    h5::quiet();
    if (H5Fis_hdf5(file.c_str()) <= 0)
        throw std::runtime_error(file + ": not an HDF5 file (or truncated before its superblock)");
    J j;
    Held held;
    try {
        const h5::Id f(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
        if (!f.valid()) throw h5::Error("cannot open (truncated or corrupt)");
        j = h5read::header(f.get(), held);
        j["obstacles"] = h5read::obstacles(f.get());
        const std::int64_t agents = j["agents"].get<std::int64_t>(), frames = j["frames"].get<std::int64_t>();
        if (agents < 1 || agents > 10'000'000) throw h5::Error("attribute agents: expected 1 to 10,000,000");
        if (frames < 1 || frames > 100'000'000) throw h5::Error("attribute frames: expected 1 to 100,000,000");
        const bool older = j["version"].get<std::int64_t>() < kRecordVersion;
        j["tracks"] = tracks(f.get(), frames, std::size_t(agents), held, older);
        j["choices"] = choices(f.get(), j["dt"].get<double>(), held);
        candidates(f.get(), j["choices"], held, older);
    } catch (const h5::Error& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
    RecordFile out;
    out.record = record_from_json(j, file);
    out.summary_json = stored_summary(j);
    if (j.contains("metrics")) out.metrics_json = j["metrics"].dump();
    out.note = h5read::note(file, held);
    return out;
}

}  // namespace mobb::crowd
