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

// Positions whose current() is worked out ahead of the commits (foresee, and beside a round of evaluating
// again): at most kAhead, kAheadGrain a task, in a step of the pool when at least kParallelAhead.
constexpr std::size_t kAhead = 512, kParallelAhead = 64, kAheadGrain = 16;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void check(const CrowdOptions& o) {
    const bool agents = o.agents >= 1 || !o.placed.empty();
    if (!agents || !(o.seconds > 0) || !(o.world.width() > 0) || !(o.world.height() > 0))
        throw std::invalid_argument("crowd: agents, seconds and the world must be positive");
    if (o.threads < 1) throw std::invalid_argument("crowd: threads must be at least 1");
    if (o.max_batch < 1) throw std::invalid_argument("crowd: max_batch must be at least 1");
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
      policy_(make_policy(o.select, {g, o.world, escapes_.in_place, goals_of(o), o.goal_radius, o.tuning,
                                     escapes_.stand_clearance, escapes_.turn_clearance})),
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

// The boxes the plan at position i puts in place and the ones it releases, appended to the worker's own
// list: positions in parallel, as they are evaluated.
void Simulation::find_boxes(std::size_t i, int worker) {
    std::vector<SpaceTimeBox>& boxes = found_[std::size_t(worker)];
    const std::size_t begin = boxes.size();
    slots_[i].boxes(boxes);
    for (int id : agents_[std::size_t(slots_[i].agent())].reserved) boxes.push_back(box_of(pieces_[std::size_t(id)]));
    spans_[i] = {worker, begin, boxes.size()};
}

// The boxes of the frame's plans (find_boxes), by position in the batch, entered in parallel (BatchGrid::fill).
void Simulation::gather(std::size_t n) {
    chosen_.clear();
    chosen_.fill(
        n,
        [&](std::size_t i) {
            const BoxSpan& b = spans_[i];
            const SpaceTimeBox* boxes = found_[std::size_t(b.worker)].data();
            return BatchGrid::Span{boxes + b.begin, boxes + b.end};
        },
        pool_);
}

// What the commit loop reads of position i's evaluation, by position (the slots lie apart): whether it
// reroutes others, the bounds of what it queried, and what its commit adds and releases.
void Simulation::outline(std::size_t i) {
    reroutes_[i] = !slots_[i].reroutes().empty();
    bounds_[i] = slots_[i].queried_bounds();
    count_commit(i, commits_[i]);
}

// Whether the evaluation at position i is still the one the state now gives: no plan committed since
// the state it read (seen_) touches what it queried - plans as first chosen (chosen_; for a first
// evaluation touched_ holds the answer) or as chosen again (moved_).
bool Simulation::current(std::size_t i) const {
    const Choice& c = slots_[i];
    const int from = seen_[i], below = int(i);
    const bool first_changed = from == 0 ? touched_[i] >= 0 : c.affected_by(chosen_, from, below);
    if (first_changed) return false;
    // Most positions meet no plan chosen again: told from the lists by position, without reading the slot.
    if (moved_.last_index() < from) return true;
    const std::optional<SpaceTimeBox>& bounds = bounds_[i];
    return !bounds || !moved_.any_between(*bounds, from, below) || !c.affected_by(moved_, from, below);
}

// current() of the positions from i on, worked out apart against moved_ and seen_ as they are: the
// answers current() would give in turn, for any number of threads, as long as the caller brings them up
// to date when moved_ grows (recheck) and drops them when a re-evaluation changes seen_. They go up to
// the next position known to be stale (first evaluated, and touched by a plan chosen before it), where a
// re-evaluation will drop the rest; in parallel when that is far enough to be worth a round of the pool.
// With no box moved yet current() reads the lists alone, cheaper than a round.
std::size_t Simulation::foresee(std::size_t i, std::size_t n) {
    if (moved_.last_index() < 0) {
        current_[i] = current(i);
        return i + 1;
    }
    std::size_t end = i;
    while (end < std::min(n, i + kAhead) && !(seen_[end] == 0 && touched_[end] >= 0)) ++end;
    if (end == i) {  // stale: the caller evaluates it again
        current_[i] = 0;
        return i + 1;
    }
    if (end - i < kParallelAhead) {
        for (std::size_t k = i; k < end; ++k) current_[k] = current(k);
        return end;
    }
    pool_.for_each(
        end - i, [&](std::size_t k, int) { current_[i + k] = current(i + k); }, kAheadGrain);
    return end;
}

// Position i's boxes joined moved_: the positions after it worked out ahead that were current may not
// be any more. Only those whose evaluation came before i and whose queries reach its boxes can change
// (a moved box never makes a stale position current), and they are worked out again.
void Simulation::recheck(std::size_t i, std::size_t known) {
    if (boxes_.empty()) return;
    SpaceTimeBox all = boxes_.front();
    for (const SpaceTimeBox& b : boxes_) all.enclose(b);
    for (std::size_t k = i + 1; k < known; ++k) {
        const std::optional<SpaceTimeBox>& bounds = bounds_[k];
        if (current_[k] && seen_[k] <= int(i) && bounds && bounds->overlaps(all)) current_[k] = current(k);
    }
}

// The evaluation at position p is out of date: p is evaluated again against the state after the commits
// before it, and with it, in parallel, the next kRound - 1 positions whose first evaluations only plans
// committed already touched, among the next kScan. Their new evaluations stay current unless a commit
// from p on touches them too (then they are evaluated again in their turn). Rounds depend on the batch
// alone, not on the thread count. In the same step, what foresee() would do next: current() of the
// positions after p up to the next one known to be stale, against moved_ as it is - recheck() brings them
// up to date as the boxes of p and of the round join it. Returns the position current_ is known up to.
std::size_t Simulation::reevaluate_from(std::size_t p, std::size_t n, const CrowdState& s) {
    constexpr std::size_t kRound = 32;  // enough to share among the threads, few enough to seldom go stale
    // Where agents are numbered in space (a scenario's regions), most positions ahead wait on commits
    // still to come: an unbounded search would read the rest of the batch for every stale position.
    constexpr std::size_t kScan = 16 * kRound;
    flush();
    round_.assign(1, p);
    for (std::size_t k = p + 1; k < std::min(n, p + kScan) && round_.size() < kRound; ++k)
        if (seen_[k] == 0 && touched_[k] >= 0 && touched_[k] < int(p)) round_.push_back(k);
    const std::size_t end = known_after_round(p, n);
    const std::size_t rounds = round_.size(), chunks = (end - (p + 1) + kAheadGrain - 1) / kAheadGrain;
    const auto task = [&](std::size_t t, int) {
        if (t < rounds) {
            const std::size_t k = round_[t];
            evaluate(k, s);
            outline(k);
            seen_[k] = int(p);
            if (k > p) current_[k] = current(k);
            return;
        }
        const std::size_t first = p + 1 + (t - rounds) * kAheadGrain;
        for (std::size_t k = first; k < std::min(end, first + kAheadGrain); ++k)  // the round's own are its tasks'
            if (!std::binary_search(round_.begin(), round_.end(), k)) current_[k] = current(k);
    };
    if (rounds > 1 || end - (p + 1) >= kParallelAhead) {
        pool_.for_each(rounds + chunks, task);
    } else {  // p alone and a few positions ahead: not worth a step of the pool
        for (std::size_t t = 0; t < rounds + chunks; ++t) task(t, 0);
    }
    return end;
}

// Where foresee() would stop after the round at p: the next position first evaluated and touched that
// the round leaves out (it will be stale), within kAhead.
std::size_t Simulation::known_after_round(std::size_t p, std::size_t n) const {
    std::size_t end = p + 1, r = 1;
    for (; end < std::min(n, p + 1 + kAhead); ++end) {
        if (r < round_.size() && round_[r] == end) {
            ++r;
            continue;
        }
        if (seen_[end] == 0 && touched_[end] >= 0) break;
    }
    return end;
}

// Four steps, the same for any number of threads: (1) every choice point of the frame is evaluated
// against the state before the frame (in parallel); (2) the boxes their plans take and release are
// gathered; (3) each choice point checks whether a plan chosen before it in the frame could change its
// evaluation (in parallel); (4) in agent order, each commits once its evaluation is current, which a
// stale one becomes by evaluating it again against the commits before it (in parallel rounds); the
// current ones between two stale ones commit as one run (in parallel, commit.cpp). The outcome is that
// of evaluating the choice points one by one in agent order.
void Simulation::run_batch(std::int64_t frame, const std::vector<int>& batch) {
    const std::size_t n = batch.size();
    if (slots_.size() < n) slots_.resize(n);
    const CrowdState s = state();
    found_.resize(std::size_t(pool_.size()));
    for (std::vector<SpaceTimeBox>& f : found_) f.clear();
    spans_.resize(n);
    pool_.for_each(n, [&](std::size_t i, int worker) {
        slots_[i].prepare(s, batch[i], frame);
        evaluate(i, s);
        find_boxes(i, worker);
    });
    gather(n);
    touched_.resize(n);
    reroutes_.resize(n);
    bounds_.resize(n);
    commits_.resize(n);
    pool_.for_each(
        n,
        [&](std::size_t i, int) {
            touched_[i] = slots_[i].last_change(chosen_, int(i));
            outline(i);
        },
        8);
    seen_.assign(n, 0);
    current_.resize(n);
    moved_.clear();
    std::size_t from = 0;   // the first position not committed yet
    std::size_t known = 0;  // current_ holds current() for positions before this
    for (std::size_t i = 0; i < n; ++i) {
        if (i >= known) known = foresee(i, n);
        MOBB_ASSERT(bool(current_[i]) == current(i));  // worked out ahead, as it would be now
        if (!current_[i]) {
            commit_run(from, i);
            from = i;
            known = reevaluate_from(i, n, s);  // seen_ changed for positions after it
        }
        if (seen_[i] > 0) {  // evaluated again
            ++out_.summary.reevaluated;
            boxes_.clear();
            slots_[i].boxes(boxes_);
            moved_.add(int(i), boxes_);
            recheck(i, known);
        }
        if (!reroutes_[i]) continue;
        // It changes other agents' plans, which positions on either side may own: it commits alone.
        commit_run(from, i);
        commit_run(i, i + 1);
        from = i + 1;
    }
    commit_run(from, n);
    flush();
}

// A frame's choice points in batches of at most CrowdOptions::max_batch, in agent order: each batch's
// commits are in the broad phase before the next is evaluated, so the outcome is that of one batch. The
// first frame, where every agent chooses, no longer grows slots and lists for all of them. What changes
// only between frames (who waits, the broad-phase ids free again) changes after the last batch.
void Simulation::run_frame(std::int64_t frame, const std::vector<int>& batch) {
    const auto most = std::size_t(o_.max_batch);
    if (batch.size() <= most) {
        run_batch(frame, batch);
    } else {
        std::vector<int> part;
        for (std::size_t first = 0; first < batch.size(); first += most) {
            part.assign(batch.begin() + std::ptrdiff_t(first),
                        batch.begin() + std::ptrdiff_t(std::min(batch.size(), first + most)));
            run_batch(frame, part);
        }
    }
    apply_waiting();
    unused_.insert(unused_.end(), left_.begin(), left_.end());
    left_.clear();
}

void Simulation::release(int id) {
    released_.push_back(id);
    broad_.stage(released_.size(), pending_);
    broad_.stage_removed(released_.size() - 1, id);
    if (broad_.holds(id)) ++released_held_;
}

// Commits reach the broad phase in one parallel step per frame, or before a re-evaluation needs them:
// staged as they were committed (commit.cpp), entered at once.
void Simulation::flush() {
    released_held_ = flushed_held_ = 0;
    broad_.apply_staged(pool_);
    left_.insert(left_.end(), released_.begin(), released_.end());
    released_.clear();
    pending_ = 0;
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
        const std::uint64_t steps = pool_.steps();
        reach_goals(f, batch);
        const auto start = Clock::now();
        broad_.expire(f);  // clips ending by now cannot overlap a candidate starting now
        for (std::int64_t e = expired_until_; e <= f; ++e) {
            std::vector<int>& ids = ending_[std::size_t(e)];
            unused_.insert(unused_.end(), ids.begin(), ids.end());
            std::vector<int>().swap(ids);
        }
        expired_until_ = f + 1;
        run_frame(f, batch);
        out_.summary.cd_seconds += since(start);
        out_.summary.parallel_steps += pool_.steps() - steps;
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
