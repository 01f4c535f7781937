#include "mobb/crowd/record.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "mobb/util/json_text.h"

namespace mobb::crowd {

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

    /// Sorts the disks of one frame, `frame[a]` for agent a (frame[a].agent == a).
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
    FrameGrid grid;
    const auto by_pair = [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
    for (std::int64_t f0 = 0; f0 < record.frames; f0 += kBlock) {
        const std::int64_t frames = std::min(kBlock, record.frames - f0);
        double rmax = 0;  // of the block: contacts are closer than 2 rmax
        for (std::size_t a = 0; a < n; ++a)
            for (std::int64_t k = 0; k < frames; ++k) {
                const auto& s = record.tracks[a].samples[std::size_t(f0 + k)];
                block[std::size_t(k) * n + a] = {s[1], s[2], s[3], int(a)};
                rmax = std::max(rmax, s[3]);
            }
        for (std::int64_t k = 0; k < frames; ++k) {
            const std::int64_t f = f0 + k;
            grid.build(&block[std::size_t(k) * n], n, 2 * rmax);
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
    if (t.goal) out["goal"] = {(*t.goal)[0], (*t.goal)[1]};
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

World world_of(const nlohmann::json& j) {
    World w;
    const auto& v = j.at("world");
    if (v.size() == 4) {
        w.x0 = v.at(0).get<double>(), w.y0 = v.at(1).get<double>();
        w.x1 = v.at(2).get<double>(), w.y1 = v.at(3).get<double>();
    } else {
        w.x1 = v.at(0).get<double>(), w.y1 = v.at(1).get<double>();
    }
    w.walls = j.value("walls", false);
    for (const auto& poly : j.value("obstacles", nlohmann::json::array())) {
        Polygon p;
        for (const auto& q : poly) p.vertices.push_back({q.at(0).get<double>(), q.at(1).get<double>()});
        w.obstacles.push_back(std::move(p));
    }
    return w;
}

AgentTrack track_of(const nlohmann::json& t, std::int64_t frames) {
    AgentTrack track;
    if (t.contains("goal"))
        track.goal = std::array<double, 2>{t.at("goal").at(0).get<double>(), t.at("goal").at(1).get<double>()};
    for (const auto& c : t.at("clips")) {
        const auto& p = c.at("place");
        track.clips.push_back(
            {c.at("clip").get<int>(),
             c.at("start").get<std::int64_t>(),
             {p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>(), p.at(3).get<double>()},
             c.at("fallback").get<bool>(),
             c.at("commit").get<std::int64_t>()});
    }
    for (const auto& s : t.at("samples"))
        track.samples.push_back(
            {s.at(0).get<double>(), s.at(1).get<double>(), s.at(2).get<double>(), s.at(3).get<double>()});
    if (std::int64_t(track.samples.size()) != frames)
        throw std::runtime_error("a track has " + std::to_string(track.samples.size()) + " samples, expected " +
                                 std::to_string(frames));
    return track;
}

std::vector<FramedClip> escape_of(const nlohmann::json& escape, double dt) {
    std::vector<FramedClip> out;
    for (const auto& e : escape) {
        const auto frame = e.at(1).get<std::int64_t>();
        out.push_back({e.at(0).get<int>(),
                       frame,
                       {e.at(2).get<double>(), e.at(3).get<double>(), e.at(4).get<double>(), double(frame) * dt}});
    }
    return out;
}

HeldGround hold_of(const nlohmann::json& h) {
    return {{h.at(0).get<double>(), h.at(1).get<double>(), h.at(2).get<double>()}, h.at(3).get<std::int64_t>()};
}

void plan_of(const nlohmann::json& c, ChoicePoint& cp, const Record& r) {
    if (!c.contains("plan")) return;
    const auto& plan = c.at("plan");
    cp.escape = escape_of(plan.at("escape"), r.dt);
    if (plan.contains("hold")) {
        const HeldGround h = hold_of(plan.at("hold"));
        cp.holds = true;
        cp.hold = h.disk;
        cp.hold_frame = h.frame;
    }
    for (const auto& j : plan.value("reroutes", nlohmann::json::array())) {
        const HeldGround h = hold_of(j.at("hold"));
        const int agent = j.at("agent").get<int>();
        if (agent < 0 || std::size_t(agent) >= r.tracks.size())
            throw std::runtime_error("choice " + std::to_string(r.choices.size()) + ": a reroute names no agent");
        cp.reroutes.push_back({agent, escape_of(j.at("escape"), r.dt), h.disk, h.frame});
    }
}

ChoicePoint choice_of(const nlohmann::json& c, const Record& r) {
    ChoicePoint cp;
    cp.agent = c.at("agent").get<int>();
    cp.frame = c.at("frame").get<std::int64_t>();
    cp.taken = c.at("taken").get<int>();
    cp.outcome = c.value("outcome", std::string(c.at("fallback").get<bool>() ? "fallback" : "candidate"));
    cp.fallback = c.at("fallback").get<bool>();
    cp.queries = c.at("queries").get<std::uint64_t>();
    cp.tests2d = c.at("tests2d").get<std::uint64_t>();
    cp.tests3d = c.at("tests3d").get<std::uint64_t>();
    cp.samples = c.at("samples").get<std::uint64_t>();
    cp.pruned = c.at("pruned").get<std::uint64_t>();
    plan_of(c, cp, r);
    for (const auto& k : c.at("candidates")) {
        Candidate cand{k.at("clip").get<int>(),
                       k.at("outside").get<bool>(),
                       k.at("queries").get<int>(),
                       k.at("hits").get<int>(),
                       {},
                       k.value("crowded", false)};
        for (const auto& q : k.at("against")) {
            const CandidateQuery cq{q.at(0).get<int>(), q.at(1).get<int>(), q.at(2).get<int>(), q.at(3).get<int>(),
                                    q.at(4).get<int>() != 0};
            const bool solid = cq.agent == -1 && cq.commit >= 0 && cq.piece == 0;
            const bool start = cq.commit == -1 && cq.piece == -1;  // the ground the agent started on
            const bool agent = cq.agent >= 0 && std::size_t(cq.agent) < r.tracks.size() && cq.piece >= -1 &&
                               (start || (cq.commit >= 0 && std::size_t(cq.commit) < r.choices.size()));
            if (!solid && !agent)
                throw std::runtime_error("choice " + std::to_string(r.choices.size()) +
                                         ": a query names a piece not in the record");
            cand.against.push_back(cq);
        }
        cp.candidates.push_back(std::move(cand));
    }
    return cp;
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
        Record r;
        r.graph = j.at("graph").get<std::string>();
        r.dt = j.at("dt").get<double>();
        r.frames = j.at("frames").get<std::int64_t>();
        r.world = world_of(j);
        r.seed = j.at("seed").get<std::uint64_t>();
        r.tree = j.at("tree").get<std::string>();
        r.select = j.at("select").get<std::string>();
        r.scenario = j.value("scenario", std::string());
        for (const auto& t : j.at("tracks")) r.tracks.push_back(track_of(t, r.frames));
        const auto& choices = j.at("choices");
        r.choices.reserve(choices.size());
        for (const auto& c : choices) r.choices.push_back(choice_of(c, r));  // queries name earlier ones only
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file + ": " + e.what());
    } catch (const std::out_of_range& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

}  // namespace mobb::crowd
