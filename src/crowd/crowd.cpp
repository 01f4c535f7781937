#include "mobb/crowd/crowd.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "choice.h"
#include "mobb/core/angle.h"
#include "mobb/crowd/broad_phase.h"
#include "mobb/util/random.h"
#include "mobb/util/worker_pool.h"

namespace mobb::crowd {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void check(const MotionGraph& g, const std::vector<Tree>& trees, const CrowdOptions& o) {
    if (o.agents < 1 || !(o.seconds > 0) || !(o.width > 0) || !(o.height > 0))
        throw std::invalid_argument("crowd: agents, seconds and the world must be positive");
    if (o.threads < 1) throw std::invalid_argument("crowd: threads must be at least 1");
    if (trees.size() != g.clips.size()) throw std::invalid_argument("crowd: one tree per graph clip expected");
}

// The simulation: frames in order; the choice points of one frame form a batch, evaluated in parallel
// against the state at the start of the frame, then committed in agent order. A choice that a commit
// earlier in its batch could have changed is evaluated again before its own commit, so the outcome is
// that of running the choice points one by one in (frame, agent) order, for any number of threads.
class Simulation {
public:
    Simulation(const MotionGraph& g, const std::vector<Tree>& trees, const CrowdOptions& o)
        : g_(g),
          outlines_(outlines_of(g)),
          trees_(trees),
          o_(o),
          pool_(o.threads),
          broad_(o.cell, o.width, o.height),
          chosen_(o.cell, o.width, o.height) {}

    CrowdRun run(const std::function<void(double)>& progress);

private:
    CrowdState state() const { return {g_, outlines_, trees_, o_, broad_, agents_, committed_}; }
    double max_radius() const;
    void place_agents();
    void run_frames(const std::function<void(double)>& progress);
    void run_batch(std::int64_t frame, const std::vector<int>& batch);
    void commit(Choice& c);
    void flush();
    void log_queries(const Choice& c);
    void fill_samples();

    const MotionGraph& g_;
    const std::vector<ClipOutline> outlines_;
    const std::vector<Tree>& trees_;
    const CrowdOptions& o_;
    util::WorkerPool pool_;
    BroadPhase broad_;                            // committed clips still playing
    std::vector<BroadPhase::Insertion> pending_;  // committed in this frame, not yet in broad_
    BatchGrid chosen_;                            // the clips chosen by the current batch, by position
    std::vector<char> stale_;                     // per position: a clip chosen before may change it
    std::vector<SpaceTimeBox> moved_;             // new boxes of clips chosen differently on re-evaluation
    std::vector<Agent> agents_;
    std::vector<Committed> committed_;   // by broad-phase id
    std::vector<std::vector<int>> due_;  // per frame: agents at a choice point
    std::vector<Choice> slots_;          // one per choice point of a batch, reused
    CrowdRun out_;
};

double Simulation::max_radius() const {
    double rmax = 0;
    for (const GraphClip& c : g_.clips)
        for (const Sample& s : c.path.samples) rmax = std::max(rmax, s.r);
    return rmax;
}

// Random positions, rejected when closer than 2 r_max to an agent placed before. Placed agents are
// kept in a grid of cells at least 2 r_max wide, so a test reads the 3 x 3 cells around the position.
void Simulation::place_agents() {
    const double rmax = max_radius(), gap = 2 * rmax;
    if (o_.width <= gap || o_.height <= gap) throw std::invalid_argument("crowd: world smaller than an agent");
    const double cell = std::max(gap, std::sqrt(o_.width * o_.height / double(o_.agents)));
    const int nx = int(o_.width / cell) + 1, ny = int(o_.height / cell) + 1;
    std::vector<std::vector<int>> grid(std::size_t(nx) * std::size_t(ny));
    auto cell_of = [&](double v, int n) { return std::clamp(int(v / cell), 0, n - 1); };
    auto free_at = [&](const Placement& p) {
        const int cx = cell_of(p.x, nx), cy = cell_of(p.y, ny);
        for (int ix = std::max(0, cx - 1); ix <= std::min(nx - 1, cx + 1); ++ix)
            for (int iy = std::max(0, cy - 1); iy <= std::min(ny - 1, cy + 1); ++iy)
                for (int b : grid[std::size_t(ix) * std::size_t(ny) + std::size_t(iy)]) {
                    const Placement& q = agents_[std::size_t(b)].start;
                    if (!(std::hypot(q.x - p.x, q.y - p.y) >= gap)) return false;
                }
        return true;
    };
    util::Random rng(o_.seed);
    for (int a = 0; a < o_.agents; ++a) {
        Placement p;
        bool ok = false;
        for (int attempt = 0; attempt < 100000 && !ok; ++attempt) {
            p = {rng.uniform(rmax, o_.width - rmax), rng.uniform(rmax, o_.height - rmax), rng.uniform(-kPi, kPi), 0.0};
            ok = free_at(p);
        }
        if (!ok)
            throw std::invalid_argument("crowd: no room for " + std::to_string(o_.agents) + " agents " +
                                        std::to_string(gap) + " m apart in the world");
        grid[std::size_t(cell_of(p.x, nx)) * std::size_t(ny) + std::size_t(cell_of(p.y, ny))].push_back(a);
        agents_.push_back({p, {}});
    }
}

// Four steps, the same for any number of threads: (1) every choice point of the frame is evaluated
// against the clips committed before the frame (in parallel); (2) the clips they chose are gathered;
// (3) each choice point checks whether a clip chosen before it in the frame could have changed its
// evaluation (in parallel); (4) in agent order, such choice points are evaluated again against the
// clips committed so far, which also catches clips that changed in a re-evaluation, then each commits.
void Simulation::run_batch(std::int64_t frame, const std::vector<int>& batch) {
    const std::size_t n = batch.size();
    if (slots_.size() < n) slots_.resize(n);
    const CrowdState s = state();
    pool_.for_each(n, [&](std::size_t i, int) {
        slots_[i].prepare(s, batch[i], frame);
        slots_[i].evaluate(s);
    });
    chosen_.clear();
    for (std::size_t i = 0; i < n; ++i) chosen_.add(int(i), slots_[i].taken().box);
    stale_.assign(n, 0);
    pool_.for_each(
        n, [&](std::size_t i, int) { stale_[i] = slots_[i].affected_by(chosen_, int(i)); }, 8);
    moved_.clear();  // clips chosen again differently: the grid holds their old boxes
    for (std::size_t i = 0; i < n; ++i) {
        Choice& c = slots_[i];
        const auto near = [&](const SpaceTimeBox& b) { return c.affected_by(b); };
        if (stale_[i] || std::any_of(moved_.begin(), moved_.end(), near)) {
            flush();
            const int before = c.taken().clip;
            c.evaluate(s);
            ++out_.summary.reevaluated;
            if (c.taken().clip != before) moved_.push_back(c.taken().box);
        }
        commit(c);
    }
    flush();
}

// Commits reach the broad phase in one parallel step per frame, or before a re-evaluation needs them.
void Simulation::flush() {
    broad_.insert_all(pending_, pool_);
    pending_.clear();
}

void Simulation::log_queries(const Choice& c) {
    const int choice = int(out_.record.choices.size());
    for (const auto& [k, a] : c.log()) {
        const Placed& cand = c.candidate(k);
        const Committed& other = committed_[std::size_t(a.id)];
        out_.queries.push_back({choice, k, cand.clip, other.clip, cand.place, other.place, a.hit});
    }
}

void Simulation::commit(Choice& c) {
    ChoicePoint& cp = c.point();
    CrowdSummary& s = out_.summary;
    // Every clip live now overlaps the candidates in time (it started before and ends after).
    const std::uint64_t pairs = (broad_.size() + pending_.size()) * std::uint64_t(c.queried());
    cp.pruned = pairs - c.near_total();
    s.time_pairs += pairs;
    if (o_.log_queries) log_queries(c);
    const Placed& taken = c.taken();
    Agent& a = agents_[std::size_t(c.agent())];
    const int id = int(committed_.size());
    a.clips.push_back({taken.clip, taken.box.f0, taken.place, cp.fallback, std::int64_t(out_.record.choices.size())});
    committed_.push_back({c.agent(), int(a.clips.size()) - 1, taken.clip, taken.place});
    pending_.push_back({id, c.agent(), taken.box});
    if (taken.box.f1 < std::int64_t(due_.size())) due_[std::size_t(taken.box.f1)].push_back(c.agent());
    ++s.choice_points;
    s.candidates += cp.candidates.size();
    s.queries += cp.queries;
    s.tests2d += cp.tests2d;
    s.tests3d += cp.tests3d;
    s.samples += cp.samples;
    s.pruned += cp.pruned;
    s.root_rejected += c.root_rejected();
    for (const Candidate& k : cp.candidates) s.hits += std::uint64_t(k.hits);
    if (cp.fallback) {
        ++s.fallbacks;
        if (taken.outside) ++s.outside;
    }
    out_.record.choices.push_back(std::move(cp));
}

void Simulation::run_frames(const std::function<void(double)>& progress) {
    const std::int64_t frames = out_.record.frames;
    due_.assign(std::size_t(frames), {});
    for (int a = 0; a < o_.agents; ++a) due_[0].push_back(a);
    // About agents x frames / mean clip length choice points: reserving saves moving them while committing.
    std::size_t samples = 0;
    for (const GraphClip& c : g_.clips) samples += c.path.size();
    const double expected =
        double(o_.agents) * (double(frames) * double(g_.clips.size()) / double(std::max<std::size_t>(1, samples)) + 1);
    out_.record.choices.reserve(std::size_t(expected * 1.2));
    committed_.reserve(std::size_t(expected * 1.2));
    std::int64_t reported = -1;
    for (std::int64_t f = 0; f < frames; ++f) {
        std::vector<int> batch = std::move(due_[std::size_t(f)]);
        if (batch.empty()) continue;
        std::sort(batch.begin(), batch.end());  // commit order: agent ids within a frame
        const auto start = Clock::now();
        broad_.expire(f);  // clips ending by now cannot overlap a candidate starting now
        run_batch(f, batch);
        out_.summary.cd_seconds += since(start);
        if (progress && f / 30 != reported) {
            reported = f / 30;
            progress(double(f) / double(frames));
        }
    }
}

void Simulation::fill_samples() {
    const std::int64_t frames = out_.record.frames;
    pool_.for_each(agents_.size(), [&](std::size_t a, int) {
        AgentTrack& t = out_.record.tracks[a];
        t.clips = std::move(agents_[a].clips);
        t.samples.reserve(std::size_t(frames));
        std::size_t k = 0;
        Rigid2 m = Rigid2::of(t.clips[0].place);  // the core's own transform, so the check rounds as the queries do
        for (std::int64_t f = 0; f < frames; ++f) {
            if (k + 1 < t.clips.size() && t.clips[k + 1].start <= f) m = Rigid2::of(t.clips[++k].place);
            const PlacedClip& c = t.clips[k];
            const Sample& s = g_.clips[std::size_t(c.clip)].path.samples[std::size_t(f - c.start)];
            t.samples.push_back({double(f) * g_.dt(), m.apply_x(s.x, s.y), m.apply_y(s.x, s.y), s.r});
        }
    });
}

CrowdRun Simulation::run(const std::function<void(double)>& progress) {
    const auto start = Clock::now();
    Record& r = out_.record;
    r.dt = g_.dt();
    r.frames = std::max<std::int64_t>(1, std::llround(o_.seconds / r.dt));
    r.width = o_.width;
    r.height = o_.height;
    r.seed = o_.seed;
    r.select = to_string(o_.select);
    r.tracks.resize(std::size_t(o_.agents));
    CrowdSummary& s = out_.summary;
    s.agents = std::uint64_t(o_.agents);
    s.simulated_seconds = double(r.frames) * r.dt;
    s.threads = o_.threads;
    place_agents();
    run_frames(progress);
    fill_samples();
    s.seconds = since(start);
    for (const Contact& c : frame_contacts(r)) {
        ++s.contacts;
        if (!c.excused) ++s.contacts_unexcused;
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
    check(graph, trees, options);
    return Simulation(graph, trees, options).run(progress);
}

double CrowdSummary::cd_us_per_agent_second() const {
    const double n = double(agents) * simulated_seconds;
    return n > 0 ? cd_seconds * 1e6 / n : 0.0;
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
    j["reevaluated"] = s.reevaluated;
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
        << "re-evaluated choices     " << s.reevaluated << " (a commit earlier in the frame was near)\n"
        << "simulation time          " << s.seconds << " s (" << s.threads << " threads)\n"
        << "collision detection      " << s.cd_seconds << " s, " << s.cd_us_per_agent_second()
        << " us per agent per simulated s\n";
    return out.str();
}

}  // namespace mobb::crowd
