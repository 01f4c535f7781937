// Committing a batch's choice points (issue 46): the plans they chose become the agents' reservations.
// The outcome is that of committing them one by one in batch position order, for any number of threads.
#include <algorithm>
#include <cstdint>

#include "mobb/core/assert.h"
#include "rules/give_way.h"
#include "sim/simulation.h"

namespace mobb::crowd {

namespace {

// Runs shorter than this commit on the calling thread: waking the pool would cost more than it saves.
constexpr std::size_t kParallelRun = 16;
constexpr std::size_t kRunGrain = 8;  // positions a worker takes at a time

// The counts a commit adds to the summary (count_choice, below), from a worker's tally.
void add_counts(CrowdSummary& to, const CrowdSummary& from) {
    to.choice_points += from.choice_points;
    to.candidates += from.candidates;
    to.queries += from.queries;
    to.tests2d += from.tests2d;
    to.tests3d += from.tests3d;
    to.samples += from.samples;
    to.pruned += from.pruned;
    to.time_pairs += from.time_pairs;
    to.root_rejected += from.root_rejected;
    to.hits += from.hits;
    to.escapes += from.escapes;
    to.right_of_way += from.right_of_way;
    to.reroutes += from.reroutes;
    to.fallbacks += from.fallbacks;
    to.fallbacks_meeting_solids += from.fallbacks_meeting_solids;
}

// A committed choice point's counts, added to `s`.
void count_choice(const Choice& c, const ChoicePoint& cp, CrowdSummary& s) {
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

}  // namespace

// Positions [from, to), every one current: committed as one step. An agent has one choice point in a
// batch, and a position that reroutes other agents commits alone (Simulation::run_batch), so the
// positions of a run write to agents of their own. What they share - piece ids, the pending and released
// lists, the live count - is laid out beforehand from each position's counts (prefix sums); what must go
// in position order (the policy, the waiting agents, a sink that keeps the record) follows on one thread.
// The counts are summed per worker, then added: sums of integers, the same in any order.
void Simulation::commit_run(std::size_t from, std::size_t to) {
    if (from == to) return;
    const std::size_t m = to - from;
    tallies_.assign(std::size_t(pool_.size()), {});
    const bool parallel = m >= kParallelRun;
    const auto each = [&](std::size_t n, std::size_t grain, auto&& f) {
        if (!parallel) {
            for (std::size_t k = 0; k < n; ++k) f(k, 0);
            return;
        }
        pool_.for_each(n, f, grain);
    };
    if (reroutes_[from]) {  // its count is taken again: the reroutes' plans as they are now
        MOBB_ASSERT(m == 1);
        count_commit(from, commits_[from]);
    }
    lay_out(from, to);
    // The commits, and beside them the lists by frame, shared out by frame (each list filled in position
    // order by one worker; from what count_commit and lay_out found, which apply_commit leaves alone).
    const std::size_t parts = parallel ? std::size_t(pool_.size()) : 1;
    each(m + parts, kRunGrain, [&](std::size_t k, int worker) {
        if (k < m) return apply_commit(from + k, commits_[from + k], tallies_[std::size_t(worker)]);
        list_commits(from, to, k - m, parts);
    });
    for (std::size_t i = from; i < to; ++i) finish_commit(i, commits_[i]);
    for (const CrowdSummary& t : tallies_) add_counts(out_.summary, t);
}

// The run's commits into the lists by frame whose frame is `part` modulo `parts`: the clips that end then
// (expired then: BroadPhase::expire) and the agents at a choice point then.
void Simulation::list_commits(std::size_t from, std::size_t to, std::size_t part, std::size_t parts) {
    const auto mine = [&](std::int64_t frame, std::size_t size) {
        return frame < std::int64_t(size) && std::size_t(frame) % parts == part;
    };
    for (std::size_t i = from; i < to; ++i) {
        const Commit& at = commits_[i];
        if (mine(at.clip_f1, ending_.size())) ending_[std::size_t(at.clip_f1)].push_back(at.clip_id);
        if (mine(at.end, due_.size())) due_[std::size_t(at.end)].push_back(at.agent);
    }
}

// What the commit at position i adds and releases: read-only, so positions count in parallel, as they are
// evaluated. It stays true until the commit: an agent's reservations change only by its own commit or by
// a reroute, and agents at a choice point are never rerouted (may_reroute), so only the reroutes' count
// is taken again, when the position commits (alone).
void Simulation::count_commit(std::size_t i, Commit& out) const {
    const Choice& c = slots_[i];
    const auto count = [&](int agent, const Plan& plan) {
        out.pieces += std::uint32_t(plan.escape.size() + (plan.hold ? 1 : 0));
        for (int id : agents_[std::size_t(agent)].reserved) {
            ++out.released;
            if (broad_.holds(id)) ++out.released_held;
        }
    };
    out = {};
    out.agent = c.agent();
    out.clip_f1 = c.taken().box.f1;
    out.end = c.taken().frame + std::int64_t(g_.clips[std::size_t(c.taken().clip)].path.size());
    out.pieces = 1;  // the clip taken
    count(c.agent(), c.plan());
    for (const Reroute& r : c.reroutes()) {
        MOBB_ASSERT(r.agent != c.agent());
        count(r.agent, r.plan);
    }
}

// The run's shared lists grown to their size, each position's place in them, and the ids its pieces take:
// the ones that left the broad phase before this frame (last first), then new ones.
void Simulation::lay_out(std::size_t from, std::size_t to) {
    std::size_t pieces = 0, released = released_.size(), pending = pending_, held = released_held_;
    std::uint64_t choice = out_.summary.choice_points;
    MOBB_ASSERT(o_.sink || out_.record.choices.size() == choice);  // the record holds every commit so far
    for (std::size_t i = from; i < to; ++i) {
        Commit& c = commits_[i];
        c.first_piece = pieces;
        c.first_release = released;
        c.choice = int(choice++);
        // A re-evaluation (seen_ > 0) leaves out of the live count the pieces released before it.
        if (seen_[i] > 0) flushed_held_ = held;
        c.live = broad_.size() + pending - flushed_held_;
        pieces += c.pieces;
        pending += c.pieces;
        released += c.released;
        held += c.released_held;
    }
    const std::size_t reused = std::min(pieces, unused_.size());
    run_ids_.resize(pieces);
    for (std::size_t j = 0; j < pieces; ++j)
        run_ids_[j] = j < reused ? unused_[unused_.size() - 1 - j] : int(pieces_.size() + (j - reused));
    for (std::size_t i = from; i < to; ++i)  // its first piece: the clip taken
        commits_[i].clip_id = run_ids_[commits_[i].first_piece];
    unused_.resize(unused_.size() - reused);
    pieces_.resize(pieces_.size() + (pieces - reused));
    run_pending_ = pending_;
    run_seq_ = placed_;
    placed_ += std::int64_t(pieces);
    pending_ = pending;
    released_.resize(released);
    broad_.stage(released, pending);
    released_held_ = held;
    if (!o_.sink) out_.record.choices.resize(std::size_t(choice));
}

// The run's j-th piece: under its id, and staged in the broad phase (entered at the next flush).
int Simulation::place_piece(Piece piece, std::size_t j) {
    const int id = run_ids_[j];
    piece.seq = run_seq_ + std::int64_t(j);
    pieces_[std::size_t(id)] = piece;
    broad_.stage_inserted(run_pending_ + j, {id, piece.agent, box_of(piece)});
    return id;
}

// Agent `agent`'s plan from now on, by choice point `choice`: what it reserved before is released.
void Simulation::reserve(int agent, int choice, const Plan& plan, Commit& at) {
    MOBB_ASSERT(agent >= 0 && std::size_t(agent) < agents_.size());
    MOBB_ASSERT(plan.escape.empty() || plan.hold);  // an escape ends on held ground
    Agent& a = agents_[std::size_t(agent)];
    for (int id : a.reserved) {
        broad_.stage_removed(at.first_release, id);
        released_[at.first_release++] = id;
    }
    a.reserved.clear();
    plan_pieces(agent, choice, plan, [&](const Piece& p) { a.reserved.push_back(place_piece(p, at.first_piece++)); });
    a.plan = plan;
}

// The commit at position i, on the agents it owns and the places lay_out gave it, counted in `tally`:
// positions in parallel.
void Simulation::apply_commit(std::size_t i, Commit& at, CrowdSummary& tally) {
    Choice& c = slots_[i];
    ChoicePoint& cp = c.point();
    // Every piece live now overlaps the candidates in time (it started before and ends after).
    const std::uint64_t pairs = at.live * std::uint64_t(c.queried());
    cp.pruned = pairs > c.near_total() ? pairs - c.near_total() : 0;
    tally.time_pairs += pairs;
    Agent& a = agents_[std::size_t(c.agent())];
    const BoxedClip& t = c.taken();
    a.clips.push_back({t.clip, t.frame, t.place, cp.fallback, at.choice});
    if (stream_) {  // the stream keeps them
        stream_->clip(c.agent(), a.clips.back());
        a.clips.erase(a.clips.begin(), a.clips.end() - 1);
    }
    Piece clip;
    clip.agent = c.agent();
    clip.choice = at.choice;
    clip.clip = t;
    place_piece(clip, at.first_piece++);
    reserve(c.agent(), at.choice, c.plan(), at);
    for (const auto& [x, y, seconds] : c.learned()) a.learned.raise(x, y, seconds);
    for (const Reroute& r : c.reroutes()) reserve(r.agent, at.choice, r.plan, at);
    at.settles = c.outcome() == Outcome::Arrived && !a.arrived && a.plan.hold;
    if (at.settles) a.arrived = true;
    note_waiting(c, a, at);
    count_choice(c, cp, tally);
    if (!o_.sink) hand_over(cp, [&](ChoicePoint& p) { out_.record.choices[std::size_t(at.choice)] = std::move(p); });
}

// Waiting: taking its escape, or choosing to stay in place (the random mode has no escapes); and giving way
// (rules/give_way.h): whether the agent waits from the end of its clip on.
void Simulation::note_waiting(const Choice& c, Agent& a, Commit& at) const {
    const bool avoids = policy_->avoids();
    const int clip = c.taken().clip;
    const bool stays = avoids && escapes_.in_place[std::size_t(clip)];
    a.choices_waited = c.outcome() == Outcome::Escape || stays ? a.choices_waited + 1 : 0;
    if (!avoids || escapes_.moves[std::size_t(clip)]) a.waiting_since = at.end;
    const bool waiting = waits(o_.tuning.give_way, a, at.end, g_.dt(), avoids);
    at.wait = waiting ? 1 : in_waiting_[std::size_t(c.agent())] ? 0 : -1;
}

// Hands `cp` to `take` without its candidates unless the run records queries: the slot keeps their memory
// for its next choice point.
template <class Take>
void Simulation::hand_over(ChoicePoint& cp, Take&& take) const {
    if (o_.record_queries) return take(cp);
    std::vector<Candidate> candidates = std::move(cp.candidates);  // leaves cp.candidates empty
    take(cp);
    // Assigning a member of the moved-from slot is defined; Choice::prepare resets the rest.
    cp.candidates = std::move(candidates);  // NOLINT(bugprone-use-after-move)
}

// What goes in position order: the policy, the waiting agents and a sink that keeps the record.
void Simulation::finish_commit(std::size_t i, const Commit& at) {
    // From `at`, not the slot: the slot was written by another worker, `at` is read in order.
    if (o_.log_queries) log_queries(slots_[i], at.choice);
    if (at.settles) {
        const Hold& h = *agents_[std::size_t(at.agent)].plan.hold;
        policy_->settled(h.x, h.y, h.r);
    }
    if (at.wait >= 0) wait_changes_.push_back({at.agent, at.wait == 1});
    if (!o_.sink || !o_.sink->keeps_commits()) return;
    o_.sink->clip(at.agent, agents_[std::size_t(at.agent)].clips.back());
    hand_over(slots_[i].point(), [&](ChoicePoint& p) { o_.sink->choice(std::size_t(at.choice), p); });
}

void Simulation::log_queries(const Choice& c, int choice) {
    for (LoggedQuery q : c.log()) {
        q.choice = choice;
        out_.queries.push_back(q);
    }
}

}  // namespace mobb::crowd
