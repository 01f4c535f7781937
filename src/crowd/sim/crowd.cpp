#include "mobb/crowd/sim/crowd.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "mobb/core/angle.h"
#include "mobb/core/assert.h"
#include "mobb/crowd/collision/broad_phase.h"
#include "mobb/util/random.h"
#include "mobb/util/worker_pool.h"
#include "rules/give_way.h"
#include "rules/stand_near_walls.h"
#include "sim/simulation.h"

namespace mobb::crowd {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void check(const CrowdOptions& o) {
    const bool agents = o.agents >= 1 || !o.placed.empty();
    if (!agents || !(o.seconds > 0) || !(o.world.width() > 0) || !(o.world.height() > 0))
        throw std::invalid_argument("crowd: agents, seconds and the world must be positive");
    if (o.threads < 1) throw std::invalid_argument("crowd: threads must be at least 1");
}

// The solids by index in a grid of their own: they never change, and a scenario may have many.
BroadPhase solid_grid(const std::vector<Polygon>& solids, const CrowdOptions& o) {
    BroadPhase grid(o.cell, o.world.x0, o.world.y0, o.world.x1, o.world.y1);
    for (int k = 0; k < int(solids.size()); ++k) {
        const auto b = bounds(solids[std::size_t(k)]);
        grid.insert(k, -1,
                    {b[0], b[1], b[2], b[3], std::numeric_limits<std::int64_t>::min(),
                     std::numeric_limits<std::int64_t>::max()});
    }
    return grid;
}

std::vector<std::array<double, 2>> goals_of(const CrowdOptions& o) {
    std::vector<std::array<double, 2>> out;
    for (const AgentSpec& a : o.placed) out.insert(out.end(), a.goals.begin(), a.goals.end());
    return out;
}

}  // namespace

Simulation::Simulation(const MotionGraph& g, const NarrowPhase& narrow, const CrowdOptions& o)
    : g_(g),
      outlines_(outlines_of(g)),
      narrow_(narrow),
      o_(o),
      escapes_(EscapeTable::build(g, o.tuning)),
      policy_(make_policy(o.select, {g, o.world, escapes_.in_place, goals_of(o), o.goal_radius, o.tuning})),
      hold_clearance_(hold_clearance(o.tuning.stand_near_walls, *policy_, escapes_)),
      solids_(policy_->avoids() ? o.world.solids() : std::vector<Polygon>{}),
      solid_grid_(solid_grid(solids_, o)),
      pool_(o.threads),
      broad_(o.cell, o.world.x0, o.world.y0, o.world.x1, o.world.y1),
      chosen_(2 * o.cell, o.world.x0, o.world.y0, o.world.x1, o.world.y1),
      moved_(2 * o.cell, o.world.x0, o.world.y0, o.world.x1, o.world.y1),
      waiting_(o.cell, o.world.x0, o.world.y0, o.world.x1, o.world.y1) {}

// Evaluates the choice point at batch position i against the state as it is now and fills its record
// entry from the plan: it reads only the state and its slot, so positions run in parallel.
void Simulation::evaluate(std::size_t i, const CrowdState& s) {
    Choice& c = slots_[i];
    c.evaluate(s);
    record_plan(c, c.point());
}

// The boxes the frame's plans put in place and the ones they release, by position in the batch: found in
// parallel (each worker appends to a list of its own), then entered in position order.
void Simulation::gather(std::size_t n) {
    found_.resize(std::size_t(pool_.size()));
    for (std::vector<SpaceTimeBox>& f : found_) f.clear();
    spans_.resize(n);
    pool_.for_each(
        n,
        [&](std::size_t i, int worker) {
            std::vector<SpaceTimeBox>& boxes = found_[std::size_t(worker)];
            const std::size_t begin = boxes.size();
            slots_[i].boxes(boxes);
            for (int id : agents_[std::size_t(slots_[i].agent())].reserved)
                boxes.push_back(box_of(pieces_[std::size_t(id)]));
            spans_[i] = {worker, begin, boxes.size()};
        },
        8);
    chosen_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        const BoxSpan& b = spans_[i];
        const SpaceTimeBox* boxes = found_[std::size_t(b.worker)].data();
        chosen_.add(int(i), boxes + b.begin, boxes + b.end);
    }
}

// Whether the evaluation at position i is still the one the state now gives: no plan committed since
// the state it read (seen_) touches what it queried - plans as first chosen (chosen_; for a first
// evaluation touched_ holds the answer) or as chosen again (moved_).
bool Simulation::current(std::size_t i) const {
    const Choice& c = slots_[i];
    const int from = seen_[i], below = int(i);
    const bool first_changed = from == 0 ? touched_[i] >= 0 : c.affected_by(chosen_, from, below);
    return !first_changed && !c.affected_by(moved_, from, below);
}

// The evaluation at position p is out of date: p is evaluated again against the state after the commits
// before it, and with it, in parallel, the next kRound - 1 positions whose first evaluations only plans
// committed already touched. Their new evaluations stay current unless a commit from p on touches them
// too (then they are evaluated again in their turn). Rounds depend on the batch alone, not on the thread
// count.
void Simulation::reevaluate_from(std::size_t p, std::size_t n, const CrowdState& s) {
    constexpr std::size_t kRound = 32;  // enough to share among the threads, few enough to seldom go stale
    flush();
    round_.assign(1, p);
    for (std::size_t k = p + 1; k < n && round_.size() < kRound; ++k)
        if (seen_[k] == 0 && touched_[k] >= 0 && touched_[k] < int(p)) round_.push_back(k);
    pool_.for_each(round_.size(), [&](std::size_t r, int) { evaluate(round_[r], s); });
    for (std::size_t k : round_) seen_[k] = int(p);
}

// The commit loop is serial and waits on memory (agents, pieces, the broad phase's items, each at a
// random place, and the evaluations in the other workers' caches): what the commits a few positions on
// will touch is fetched ahead, in three steps since each step's addresses are read from the one before.
void Simulation::prefetch_commit(std::size_t i, std::size_t n) {
    constexpr std::size_t kAhead = 4;  // positions between the steps
    if (i + 3 * kAhead < n) {
        const char* a = reinterpret_cast<const char*>(&agents_[std::size_t(slots_[i + 3 * kAhead].agent())]);
        for (std::size_t b = 0; b < sizeof(Agent); b += 64) __builtin_prefetch(a + b);
    }
    if (i + 2 * kAhead < n) {
        const Agent& a = agents_[std::size_t(slots_[i + 2 * kAhead].agent())];
        __builtin_prefetch(a.reserved.data());
        __builtin_prefetch(a.clips.data());
    }
    if (i + kAhead < n) {
        Choice& c = slots_[i + kAhead];  // written by whichever worker evaluated it
        __builtin_prefetch(&c.taken());
        __builtin_prefetch(&c.plan());
        __builtin_prefetch(&c.point());
        __builtin_prefetch(c.point().candidates.data());
        for (int id : agents_[std::size_t(c.agent())].reserved) {
            __builtin_prefetch(&pieces_[std::size_t(id)]);
            broad_.prefetch(id);
        }
        if (stream_) stream_->prefetch(c.agent());
    }
}

// Four steps, the same for any number of threads: (1) every choice point of the frame is evaluated
// against the state before the frame (in parallel); (2) the boxes their plans take and release are
// gathered; (3) each choice point checks whether a plan chosen before it in the frame could change its
// evaluation (in parallel); (4) in agent order, each commits once its evaluation is current, which a
// stale one becomes by evaluating it again against the commits before it (in parallel rounds). The
// outcome is that of evaluating the choice points one by one in agent order.
void Simulation::run_batch(std::int64_t frame, const std::vector<int>& batch) {
    const std::size_t n = batch.size();
    if (slots_.size() < n) slots_.resize(n);
    const CrowdState s = state();
    pool_.for_each(n, [&](std::size_t i, int) {
        slots_[i].prepare(s, batch[i], frame);
        evaluate(i, s);
    });
    gather(n);
    touched_.resize(n);
    pool_.for_each(
        n, [&](std::size_t i, int) { touched_[i] = slots_[i].last_change(chosen_, int(i)); }, 8);
    seen_.assign(n, 0);
    moved_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        prefetch_commit(i, n);
        if (!current(i)) reevaluate_from(i, n, s);
        Choice& c = slots_[i];
        // Position 0 is always current: seen_ > 0 marks a re-evaluation, before which the record's live
        // count leaves out the pieces released so far (see commit()).
        const bool again = seen_[i] > 0;
        if (again) flushed_held_ = released_held_;
        commit(c);
        if (!again) continue;
        ++out_.summary.reevaluated;
        boxes_.clear();
        c.boxes(boxes_);
        moved_.add(int(i), boxes_);
    }
    flush();
    apply_waiting();
    unused_.insert(unused_.end(), left_.begin(), left_.end());
    left_.clear();
    if (frame == 0) release_batch();
}

// The first frame holds every agent's first choice point; a later one holds the agents whose clips end
// there, a few percent of them. What the first grew (the slots and their lists, the batch's boxes) is
// given back after it rather than held for the whole run: at a million agents, gigabytes.
void Simulation::release_batch() {
    slots_ = {};
    found_ = {};
    spans_ = {};
    touched_ = {};
    seen_ = {};
    chosen_.release();
    moved_.release();
}

void Simulation::release(int id) {
    released_.push_back(id);
    if (broad_.holds(id)) ++released_held_;
}

// Commits reach the broad phase in one parallel step per frame, or before a re-evaluation needs them.
void Simulation::flush() {
    released_held_ = flushed_held_ = 0;
    broad_.update(released_, pending_, pool_);
    left_.insert(left_.end(), released_.begin(), released_.end());
    released_.clear();
    pending_.clear();
}

void Simulation::log_queries(const Choice& c) {
    const int choice = int(out_.summary.choice_points);
    for (LoggedQuery q : c.log()) {
        q.choice = choice;
        out_.queries.push_back(q);
    }
}

void Simulation::record_plan(const Choice& c, ChoicePoint& cp) const {
    static const char* const kOutcomes[] = {"candidate", "escape", "arrived", "fallback", "right of way"};
    cp.outcome = kOutcomes[int(c.outcome())];
    cp.escape.clear();
    for (const BoxedClip& e : c.plan().escape) cp.escape.push_back({e.clip, e.frame, e.place});
    cp.intended.clear();
    for (const SearchStep& e : c.intended()) cp.intended.push_back({e.clip, e.frame, e.place});
    cp.holds = c.plan().hold.has_value();
    if (cp.holds) {
        const Hold& h = *c.plan().hold;
        cp.hold = {h.x, h.y, h.r};
        cp.hold_frame = h.frame;
    }
    cp.reroutes.clear();
    for (const Reroute& r : c.reroutes()) {
        MOBB_ASSERT(r.plan.hold);  // a reroute is a way to stop: it ends on held ground
        ReroutedPlan& out = cp.reroutes.emplace_back();
        out.agent = r.agent;
        for (const BoxedClip& e : r.plan.escape) out.escape.push_back({e.clip, e.frame, e.place});
        out.hold = {r.plan.hold->x, r.plan.hold->y, r.plan.hold->r};
        out.hold_frame = r.plan.hold->frame;
    }
}

void Simulation::count(const Choice& c, const ChoicePoint& cp) {
    CrowdSummary& s = out_.summary;
    ++s.choice_points;
    s.candidates += cp.candidates.size();
    s.queries += cp.queries;
    s.tests2d += cp.tests2d;
    s.tests3d += cp.tests3d;
    s.samples += cp.samples;
    s.pruned += cp.pruned;
    s.root_rejected += c.root_rejected();
    for (const Candidate& k : cp.candidates) s.hits += std::uint64_t(k.hits);
    if (c.outcome() == Outcome::Escape) ++s.escapes;
    if (c.outcome() == Outcome::RightOfWay) ++s.right_of_way, s.reroutes += c.reroutes().size();
    if (cp.fallback) {
        ++s.fallbacks;
        for (const Candidate& k : cp.candidates)
            if (k.clip == cp.taken && k.meets_solid) {
                ++s.fallbacks_meeting_solids;
                break;
            }
    }
}

// Agent `agent`'s plan from now on, by choice point `choice`: what it reserved before is released.
void Simulation::reserve(int agent, int choice, const Plan& plan) {
    MOBB_ASSERT(agent >= 0 && std::size_t(agent) < agents_.size());
    MOBB_ASSERT(plan.escape.empty() || plan.hold);  // an escape ends on held ground
    Agent& a = agents_[std::size_t(agent)];
    for (int id : a.reserved) release(id);
    a.reserved.clear();
    Piece p;
    p.agent = agent;
    p.choice = choice;
    for (std::size_t i = 0; i < plan.escape.size(); ++i) {
        p.index = int(i) + 1;
        p.clip = plan.escape[i];
        a.reserved.push_back(add_piece(p, true));
    }
    if (plan.hold) {
        p.kind = Piece::Held;
        p.index = -1;
        p.hold = *plan.hold;
        a.reserved.push_back(add_piece(p, true));
    }
    a.plan = plan;
}

// Giving way (rules/give_way.h): whether the agent waits from the end of the clip it took (`end`) on:
// others' walks keep clear of it from the next frame on, until it moves.
void Simulation::note_waiting(int agent, std::int64_t end) {
    const Agent& a = agents_[std::size_t(agent)];
    const bool waiting = waits(o_.tuning.give_way, a, end, g_.dt(), policy_->avoids());
    if (!waiting && !in_waiting_[std::size_t(agent)]) return;
    wait_changes_.push_back({agent, waiting});
}

void Simulation::apply_waiting() {
    for (const auto& [agent, waiting] : wait_changes_) {
        in_waiting_[std::size_t(agent)] = waiting;
        if (!waiting) {
            waiting_.remove(agent);
            continue;
        }
        const Hold& h = *agents_[std::size_t(agent)].plan.hold;
        waiting_at_[std::size_t(agent)] = {h.x, h.y};
        waiting_.insert(agent, agent, waiting_ground(o_.tuning.give_way, h));
    }
    wait_changes_.clear();
}

void Simulation::commit(Choice& c) {
    ChoicePoint& cp = c.point();
    // Every piece live now overlaps the candidates in time (it started before and ends after). Live as the
    // record has always counted them: the released pieces out once a stale choice point before in the
    // frame was evaluated again, as when each was evaluated again alone, after a flush.
    const std::size_t live = broad_.size() + pending_.size() - flushed_held_;
    const std::uint64_t pairs = live * std::uint64_t(c.queried());
    cp.pruned = pairs > c.near_total() ? pairs - c.near_total() : 0;
    out_.summary.time_pairs += pairs;
    if (o_.log_queries) log_queries(c);
    const int choice = int(out_.summary.choice_points);  // its index: the choice points committed so far
    Agent& a = agents_[std::size_t(c.agent())];
    const BoxedClip& t = c.taken();
    a.clips.push_back({t.clip, t.frame, t.place, cp.fallback, choice});
    if (stream_) stream_->clip(c.agent(), a.clips.back()), a.clips.erase(a.clips.begin(), a.clips.end() - 1);
    Piece clip;
    clip.agent = c.agent();
    clip.choice = choice;
    clip.clip = t;
    add_piece(clip, true);
    reserve(c.agent(), choice, c.plan());
    for (const auto& [x, y, seconds] : c.learned()) a.learned.raise(x, y, seconds);
    for (const Reroute& r : c.reroutes()) reserve(r.agent, choice, r.plan);
    if (c.outcome() == Outcome::Arrived && !a.arrived && a.plan.hold) {
        a.arrived = true;
        policy_->settled(a.plan.hold->x, a.plan.hold->y, a.plan.hold->r);
    }
    // Waiting: taking its escape, or choosing to stay in place (the random mode has no escapes).
    const bool avoids = policy_->avoids();
    const bool stays = avoids && escapes_.in_place[std::size_t(t.clip)];
    a.choices_waited = c.outcome() == Outcome::Escape || stays ? a.choices_waited + 1 : 0;
    const std::int64_t end = t.frame + std::int64_t(g_.clips[std::size_t(t.clip)].path.size());
    if (!avoids || escapes_.moves[std::size_t(t.clip)]) a.waiting_since = end;
    note_waiting(c.agent(), end);
    if (end < std::int64_t(due_.size())) due_[std::size_t(end)].push_back(c.agent());
    count(c, cp);
    if (o_.sink && o_.record_queries) return o_.sink->choice(std::size_t(choice), cp);  // the record keeps none
    if (o_.record_queries) return out_.record.choices.push_back(std::move(cp));
    // Counted, and not recorded: the slot keeps the candidates' memory for its next choice point.
    std::vector<Candidate> candidates = std::move(cp.candidates);  // leaves cp.candidates empty
    if (o_.sink)
        o_.sink->choice(std::size_t(choice), cp);
    else
        out_.record.choices.push_back(std::move(cp));
    // Assigning a member of the moved-from slot is defined; Choice::prepare resets the rest.
    cp.candidates = std::move(candidates);  // NOLINT(bugprone-use-after-move)
}

// Where the agent's disk is at the frame before its choice point: the last sample of its last clip (as
// the record has it), or its start.
std::array<double, 2> Simulation::last_position(const Agent& a) const {
    if (a.clips.empty()) return {a.start.x, a.start.y};
    return clip_end(g_, a.clips.back().clip, a.clips.back().place);
}

// Agents at a choice point whose disk came within the goal radius of the goal they head for: they head
// for the next one, or - at the last, when they leave - leave the run (after one clip at least, so that
// every track has samples) and drop out of the batch.
void Simulation::reach_goals(std::int64_t frame, std::vector<int>& batch) {
    const std::size_t before = batch.size();
    std::size_t kept = 0;
    for (int agent : batch) {
        Agent& a = agents_[std::size_t(agent)];
        const auto goal = a.goal();
        if (goal && !a.stops_at_goal() && frame >= a.start_frame && !a.clips.empty()) {
            if (reaches_goal(last_position(a), *goal, o_.goal_radius)) {
                ++a.next_goal;
                a.learned.clear();  // times to go to the goal reached
            }
        }
        if (a.at_goal == AtGoal::Leave && !a.goal() && !a.clips.empty()) {
            leave(agent, frame);
            continue;
        }
        batch[kept++] = agent;
    }
    batch.resize(kept);
    if (kept == before) return;
    flush();  // the frame's choice points see the ground they left free
    apply_waiting();
}

// The agent leaves the run at `frame`: what it reserved is released, it waits no more, and it has no
// more choice points.
void Simulation::leave(int agent, std::int64_t frame) {
    Agent& a = agents_[std::size_t(agent)];
    MOBB_ASSERT(!a.left_frame && !a.clips.empty());  // leaves once, after a clip (its track has samples)
    a.left_frame = frame;
    for (int id : a.reserved) release(id);
    a.reserved.clear();
    a.plan = {};
    if (stream_) stream_->left(agent, frame);
    if (in_waiting_[std::size_t(agent)]) wait_changes_.push_back({agent, false});
}

void Simulation::run_frames(const std::function<void(double)>& progress) {
    const std::int64_t frames = out_.record.frames;
    due_.assign(std::size_t(frames), {});
    ending_.assign(std::size_t(frames), {});
    for (int a = 0; a < int(agents_.size()); ++a) due_[0].push_back(a);
    in_waiting_.assign(agents_.size(), 0);
    waiting_at_.assign(agents_.size(), {0.0, 0.0});
    // About agents x frames / mean clip length choice points: reserving saves moving them while committing.
    std::size_t samples = 0;
    for (const GraphClip& c : g_.clips) samples += c.path.size();
    const double expected = double(agents_.size()) *
                            (double(frames) * double(g_.clips.size()) / double(std::max<std::size_t>(1, samples)) + 1);
    if (!o_.sink) out_.record.choices.reserve(std::size_t(expected * 1.2));
    std::int64_t reported = -1;
    for (std::int64_t f = 0; f < frames; ++f) {
        if (stream_) stream_->until(f);  // every agent's clips cover the frames before f
        std::vector<int> batch = std::move(due_[std::size_t(f)]);
        if (batch.empty()) continue;
        std::sort(batch.begin(), batch.end());  // commit order: agent ids within a frame
        reach_goals(f, batch);
        const auto start = Clock::now();
        broad_.expire(f);  // clips ending by now cannot overlap a candidate starting now
        for (std::int64_t e = expired_until_; e <= f; ++e) {
            std::vector<int>& ids = ending_[std::size_t(e)];
            unused_.insert(unused_.end(), ids.begin(), ids.end());
            std::vector<int>().swap(ids);
        }
        expired_until_ = f + 1;
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
        t.goals = agents_[a].goals;
        t.at_goal = agents_[a].at_goal;
        t.left_frame = agents_[a].left_frame;
        const std::int64_t until = t.left_frame.value_or(frames);
        t.samples.reserve(std::size_t(until));
        std::size_t k = 0;
        Rigid2 m = Rigid2::of(t.clips[0].place);  // the core's own transform, so the check rounds as the queries do
        for (std::int64_t f = 0; f < until; ++f) {
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
    r.world = o_.world;
    if (!policy_->avoids()) r.world.walls = false;  // the paper's timing mode ignores them
    r.seed = o_.seed;
    r.select = to_string(o_.select);
    r.tree = narrow_.name();
    place_agents();
    r.tracks.resize(agents_.size());
    CrowdSummary& s = out_.summary;
    s.agents = std::uint64_t(agents_.size());
    s.simulated_seconds = double(r.frames) * r.dt;
    s.threads = o_.threads;
    if (policy_->avoids()) reserve_starts();
    if (o_.sink) {
        start_stream();
        stream_->share(pool_);
    }
    run_frames(progress);
    if (stream_) return finish_stream(start, progress);
    fill_samples();
    s.seconds = since(start);
    for (const Contact& c : frame_contacts(r)) {
        ++s.contacts;
        if (!c.excused) ++s.contacts_unexcused;
    }
    if (progress) progress(1.0);
    return std::move(out_);
}

std::vector<Tree> build_trees(const MotionGraph& graph, const TreeOptions& options) {
    std::vector<Tree> trees;
    trees.reserve(graph.clips.size());
    for (const GraphClip& c : graph.clips) trees.push_back(Tree::build(c.path, options));
    return trees;
}

CrowdRun run_crowd(const MotionGraph& graph, const NarrowPhase& narrow, const CrowdOptions& options,
                   const std::function<void(double)>& progress) {
    check(options);
    return Simulation(graph, narrow, options).run(progress);
}

}  // namespace mobb::crowd
