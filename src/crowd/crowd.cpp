#include "mobb/crowd/crowd.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <queue>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "mobb/crowd/broad_phase.h"
#include "random.h"

namespace mobb::crowd {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A candidate clip placed in the world: its space-time box and whether it stays inside.
struct Placed {
    int clip = 0;
    Placement place;
    SpaceTimeBox box;
    bool outside = false;
    double excess = 0;  // metres farther outside than at the start (ranks fallbacks)
};

// How far a point is outside the world rectangle (0 inside), metres.
double excursion(double x, double y, const CrowdOptions& o) {
    return std::max({0.0, -x, x - o.width, -y, y - o.height});
}

// A candidate "leaves the world" when its root goes farther outside the rectangle than where it
// starts, so an agent pushed out by a fallback may walk back in.
Placed place_clip(const MotionGraph& g, int clip, const Placement& p, std::int64_t frame, const CrowdOptions& o) {
    Placed out{clip, p, {}, false, 0.0};
    const Rigid2 m = Rigid2::of(p);
    const Path& path = g.clips[std::size_t(clip)].path;
    out.box = {1e300, 1e300, -1e300, -1e300, frame, frame + std::int64_t(path.size())};
    const double start = excursion(p.x, p.y, o);
    for (const Sample& s : path.samples) {
        const double x = m.apply_x(s.x, s.y), y = m.apply_y(s.x, s.y);
        out.box.x0 = std::min(out.box.x0, x - s.r);
        out.box.y0 = std::min(out.box.y0, y - s.r);
        out.box.x1 = std::max(out.box.x1, x + s.r);
        out.box.y1 = std::max(out.box.y1, y + s.r);
        out.excess = std::max(out.excess, excursion(x, y, o) - start);
    }
    out.outside = out.excess > 0;
    return out;
}

// One choice point's search, with the simulation's state it needs.
class Simulation {
public:
    Simulation(const MotionGraph& g, const std::vector<Tree>& trees, const CrowdOptions& o)
        : g_(g), trees_(trees), o_(o), rng_(o.seed), broad_(o.cell) {}

    CrowdRun run(const std::function<void(double)>& progress);

private:
    struct Agent {
        std::vector<PlacedClip> clips;
        Placement start;
    };

    void place_agents();
    void choose(int agent, std::int64_t frame);
    int count_hits(ChoicePoint& cp, int index, const Placed& c, const std::vector<int>& near, bool stop_at_hit);
    void commit(int agent, const Placed& c, bool fallback);
    void fill_samples();

    const MotionGraph& g_;
    const std::vector<Tree>& trees_;
    const CrowdOptions& o_;
    Random rng_;
    BroadPhase broad_;
    std::vector<Agent> agents_;
    std::vector<std::pair<int, int>> handles_;  // broad-phase id -> (agent, clip index)
    std::priority_queue<std::pair<std::int64_t, int>, std::vector<std::pair<std::int64_t, int>>, std::greater<>> expiry_;
    CrowdRun out_;
    std::vector<int> near_;
};

void Simulation::place_agents() {
    double rmax = 0;
    for (const GraphClip& c : g_.clips)
        for (const Sample& s : c.path.samples) rmax = std::max(rmax, s.r);
    if (o_.width <= 2 * rmax || o_.height <= 2 * rmax) throw std::invalid_argument("crowd: world smaller than an agent");
    for (int a = 0; a < o_.agents; ++a) {
        Placement p;
        bool ok = false;
        for (int attempt = 0; attempt < 100000 && !ok; ++attempt) {
            p = {rng_.uniform(rmax, o_.width - rmax), rng_.uniform(rmax, o_.height - rmax), rng_.uniform(-kPi, kPi), 0.0};
            ok = std::all_of(agents_.begin(), agents_.end(), [&](const Agent& b) {
                return std::hypot(b.start.x - p.x, b.start.y - p.y) >= 2 * rmax;
            });
        }
        if (!ok) throw std::invalid_argument("crowd: no room for " + std::to_string(o_.agents) + " agents " +
                                             std::to_string(2 * rmax) + " m apart in the world");
        agents_.push_back({{}, p});
    }
}

int Simulation::count_hits(ChoicePoint& cp, int index, const Placed& c, const std::vector<int>& near, bool stop_at_hit) {
    Candidate& cand = cp.candidates[std::size_t(index)];
    cand.queries = 0;  // a fallback reruns a candidate's queries in full: keep only the full list
    cand.against.clear();
    int hits = 0;
    for (int id : near) {
        const auto [b, k] = handles_[std::size_t(id)];
        const PlacedClip& other = agents_[std::size_t(b)].clips[std::size_t(k)];
        QueryStats st;
        const bool hit = collide(trees_[std::size_t(c.clip)], c.place, trees_[std::size_t(other.clip)], other.place, &st);
        ++cand.queries;
        cand.against.push_back({b, k, hit});
        ++cp.queries;
        cp.tests2d += st.tests2d;
        cp.tests3d += st.tests3d;
        cp.samples += st.samples;
        CrowdSummary& s = out_.summary;
        if (!hit && st.tests2d + st.tests3d <= 1 && st.samples == 0) ++s.root_rejected;
        if (o_.log_queries)
            out_.queries.push_back({int(out_.record.choices.size()), index, c.clip, other.clip, c.place, other.place, hit});
        if (hit) {
            ++hits;
            if (stop_at_hit) break;
        }
    }
    cand.hits = hits;
    return hits;
}

void Simulation::commit(int agent, const Placed& c, bool fallback) {
    Agent& a = agents_[std::size_t(agent)];
    const int id = int(handles_.size());
    a.clips.push_back({c.clip, c.box.f0, c.place, fallback, std::int64_t(out_.record.choices.size())});
    handles_.emplace_back(agent, int(a.clips.size()) - 1);
    broad_.insert(id, agent, c.box);
    expiry_.emplace(c.box.f1, id);
}

void Simulation::choose(int agent, std::int64_t frame) {
    Agent& a = agents_[std::size_t(agent)];
    std::vector<int> order;
    Placement base = a.start;
    if (a.clips.empty()) {
        order = g_.clips[std::size_t(rng_.below(int(g_.clips.size())))].successors;
    } else {
        const PlacedClip& last = a.clips.back();
        order = g_.clips[std::size_t(last.clip)].successors;
        base = g_.next(last.place, last.clip);
    }
    base.t0 = double(frame) * g_.dt();  // on the global grid, not accumulated
    for (std::size_t k = order.size(); k > 1; --k) std::swap(order[k - 1], order[std::size_t(rng_.below(int(k)))]);

    ChoicePoint cp;
    cp.agent = agent;
    cp.frame = frame;
    const bool random = o_.select == Selection::Random;
    std::vector<Placed> placed;
    std::vector<std::vector<int>> nears;
    int taken = -1;
    for (int clip : order) {
        placed.push_back(place_clip(g_, clip, base, frame, o_));
        const Placed& c = placed.back();
        cp.candidates.push_back({clip, c.outside, 0, 0, {}});
        broad_.query(c.box, agent, near_);
        nears.push_back(near_);
        out_.summary.time_pairs += broad_.size();
        cp.pruned += broad_.size() - near_.size();
        if (!random && c.outside) continue;  // dropped without queries
        const int hits = count_hits(cp, int(placed.size()) - 1, c, near_, !random);
        if (!random && hits == 0) {
            taken = int(placed.size()) - 1;
            break;
        }
    }
    if (random) {
        taken = rng_.below(int(placed.size()));
    } else if (taken < 0) {  // every candidate failed: count all collisions, take the fewest, then the least far out
        cp.fallback = true;
        for (std::size_t k = 0; k < placed.size(); ++k) count_hits(cp, int(k), placed[k], nears[k], false);
        taken = 0;
        for (std::size_t k = 1; k < placed.size(); ++k) {
            const Candidate &x = cp.candidates[k], &y = cp.candidates[std::size_t(taken)];
            if (std::make_pair(x.hits, placed[k].excess) < std::make_pair(y.hits, placed[std::size_t(taken)].excess))
                taken = int(k);
        }
        ++out_.summary.fallbacks;
        if (placed[std::size_t(taken)].outside) ++out_.summary.outside;
    }
    cp.taken = placed[std::size_t(taken)].clip;
    commit(agent, placed[std::size_t(taken)], cp.fallback);
    CrowdSummary& s = out_.summary;
    ++s.choice_points;
    s.candidates += cp.candidates.size();
    s.queries += cp.queries;
    s.tests2d += cp.tests2d;
    s.tests3d += cp.tests3d;
    s.samples += cp.samples;
    s.pruned += cp.pruned;
    for (const Candidate& c : cp.candidates) s.hits += std::uint64_t(c.hits);
    out_.record.choices.push_back(std::move(cp));
}

void Simulation::fill_samples() {
    for (std::size_t a = 0; a < agents_.size(); ++a) {
        AgentTrack& t = out_.record.tracks[a];
        t.clips = agents_[a].clips;
        std::size_t k = 0;
        for (std::int64_t f = 0; f < out_.record.frames; ++f) {
            while (k + 1 < t.clips.size() && t.clips[k + 1].start <= f) ++k;
            const PlacedClip& c = t.clips[k];
            const Sample& s = g_.clips[std::size_t(c.clip)].path.samples[std::size_t(f - c.start)];
            const Rigid2 m = Rigid2::of(c.place);  // the core's own transform, so the check rounds as the queries do
            t.samples.push_back({double(f) * g_.dt(), m.apply_x(s.x, s.y), m.apply_y(s.x, s.y), s.r});
        }
    }
}

CrowdRun Simulation::run(const std::function<void(double)>& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (o_.agents < 1 || !(o_.seconds > 0) || !(o_.width > 0) || !(o_.height > 0))
        throw std::invalid_argument("crowd: agents, seconds and the world must be positive");
    if (trees_.size() != g_.clips.size()) throw std::invalid_argument("crowd: one tree per graph clip expected");
    Record& r = out_.record;
    r.dt = g_.dt();
    r.frames = std::max<std::int64_t>(1, std::llround(o_.seconds / r.dt));
    r.width = o_.width;
    r.height = o_.height;
    r.seed = o_.seed;
    r.select = to_string(o_.select);
    r.tracks.resize(std::size_t(o_.agents));
    place_agents();
    std::priority_queue<std::pair<std::int64_t, int>, std::vector<std::pair<std::int64_t, int>>, std::greater<>> events;
    for (int a = 0; a < o_.agents; ++a) events.emplace(0, a);
    std::int64_t reported = -1;
    while (!events.empty()) {
        const auto [frame, agent] = events.top();
        events.pop();
        while (!expiry_.empty() && expiry_.top().first <= frame) {
            broad_.remove(expiry_.top().second);
            expiry_.pop();
        }
        choose(agent, frame);
        const std::int64_t end = agents_[std::size_t(agent)].clips.back().start +
                                 std::int64_t(g_.clips[std::size_t(agents_[std::size_t(agent)].clips.back().clip)].path.size());
        if (end < r.frames) events.emplace(end, agent);
        if (progress && frame / 30 != reported) {
            reported = frame / 30;
            progress(double(frame) / double(r.frames));
        }
    }
    fill_samples();
    out_.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const Contact& c : frame_contacts(r)) {
        ++out_.summary.contacts;
        if (!c.excused) ++out_.summary.contacts_unexcused;
    }
    if (progress) progress(1.0);
    return std::move(out_);
}

double per(std::uint64_t x, std::uint64_t n) { return n ? double(x) / double(n) : 0.0; }

}  // namespace

const char* to_string(Selection s) { return s == Selection::Avoid ? "avoid" : "random"; }

Selection parse_selection(const std::string& name) {
    if (name == "avoid") return Selection::Avoid;
    if (name == "random") return Selection::Random;
    throw std::invalid_argument("unknown selection '" + name + "' (avoid, random)");
}

std::vector<Tree> build_trees(const MotionGraph& graph, const TreeOptions& options) {
    std::vector<Tree> trees;
    trees.reserve(graph.clips.size());
    for (const GraphClip& c : graph.clips) trees.push_back(Tree::build(c.path, options));
    return trees;
}

CrowdRun run_crowd(const MotionGraph& graph, const std::vector<Tree>& trees, const CrowdOptions& options,
                   const std::function<void(double)>& progress) {
    return Simulation(graph, trees, options).run(progress);
}

std::string summary_json(const CrowdSummary& s) {
    nlohmann::ordered_json j;
    j["choice_points"] = s.choice_points;
    j["candidates"] = s.candidates;
    j["queries"] = s.queries;
    j["positive_queries"] = s.hits;
    j["mean_tests2d"] = per(s.tests2d, s.queries);
    j["mean_tests3d"] = per(s.tests3d, s.queries);
    j["mean_samples"] = per(s.samples, s.queries);
    j["root_rejected_share"] = per(s.root_rejected, s.queries);
    j["time_overlapping_pairs"] = s.time_pairs;
    j["pairs_pruned"] = s.pruned;
    j["fallbacks"] = s.fallbacks;
    j["fallbacks_outside_world"] = s.outside;
    j["contacts"] = s.contacts;
    j["contacts_outside_fallbacks"] = s.contacts_unexcused;
    j["simulation_seconds"] = s.seconds;
    return j.dump();
}

std::string summary_text(const CrowdSummary& s) {
    std::ostringstream out;
    out << "choice points            " << s.choice_points << " (" << s.candidates << " candidates)\n"
        << "queries                  " << s.queries << " (" << s.hits << " positive)\n"
        << "mean tests per query     2D " << per(s.tests2d, s.queries) << ", 3D " << per(s.tests3d, s.queries)
        << ", samples " << per(s.samples, s.queries) << "\n"
        << "rejected at the root     " << 100.0 * per(s.root_rejected, s.queries) << " %\n"
        << "pairs pruned (broad)     " << s.pruned << " of " << s.time_pairs << " overlapping in time\n"
        << "fallbacks                " << s.fallbacks << " (" << s.outside << " leaving the world)\n"
        << "contacts (frame check)   " << s.contacts << " agent-pair frames, " << s.contacts_unexcused
        << " outside fallbacks\n"
        << "simulation time          " << s.seconds << " s\n";
    return out.str();
}

}  // namespace mobb::crowd
