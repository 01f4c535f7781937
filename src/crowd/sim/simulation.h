// The crowd's simulation (run_crowd): its state and steps, shared by the files that implement them -
// crowd.cpp (frames, batches, commits, goals) and starts.cpp (where agents start and the ground they hold
// there). Private to src/crowd.
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "choice/choice.h"
#include "mobb/crowd/collision/broad_phase.h"
#include "mobb/crowd/sim/crowd.h"
#include "mobb/util/worker_pool.h"
#include "sim/frame_stream.h"

namespace mobb::crowd {

// The simulation: frames in order; the choice points of one frame form a batch, evaluated in parallel
// against the state at the start of the frame, then committed in agent order. A choice that a commit
// earlier in its batch could have changed is evaluated again before its own commit, so the outcome is
// that of running the choice points one by one in (frame, agent) order, for any number of threads.
class Simulation {
public:
    Simulation(const MotionGraph& g, const NarrowPhase& narrow, const CrowdOptions& o);

    CrowdRun run(const std::function<void(double)>& progress);

private:
    CrowdState state() const {
        return {g_,      outlines_,   narrow_, escapes_, *policy_, o_,       hold_clearance_,
                solids_, solid_grid_, broad_,  agents_,  pieces_,  waiting_, waiting_at_};
    }
    double max_radius() const;
    void place_agents();
    void place_at_random(double gap, double margin);
    void reserve_starts();
    std::array<double, 2> last_position(const Agent& a) const;
    void reach_goals(std::int64_t frame, std::vector<int>& batch);
    void leave(int agent, std::int64_t frame);
    void run_frames(const std::function<void(double)>& progress);
    void run_frame(std::int64_t frame, const std::vector<int>& batch);
    // Not inlined: a profile of the collision detection collects this (callgrind --toggle-collect).
    [[gnu::noinline]] void run_batch(std::int64_t frame, const std::vector<int>& batch);
    void apply_waiting();
    void evaluate(std::size_t i, const CrowdState& s);
    void find_boxes(std::size_t i, int worker);
    void gather(std::size_t n);
    void outline(std::size_t i);
    bool current(std::size_t i) const;
    std::size_t foresee(std::size_t i, std::size_t n);
    void recheck(std::size_t i, std::size_t known);
    std::size_t reevaluate_from(std::size_t p, std::size_t n, const CrowdState& s);
    std::size_t known_after_round(std::size_t p, std::size_t n) const;
    int add_piece(const Piece& piece);
    // A commit's share of a run (commit.cpp): its counts, then its places in the run's shared lists.
    struct Commit {
        std::uint32_t pieces = 0;         // pieces it adds: the clip taken, its plan's and its reroutes'
        std::uint32_t released = 0;       // pieces it releases: its agent's and the rerouted agents' plans
        std::uint32_t released_held = 0;  // how many of those the broad phase holds
        std::size_t first_piece = 0;      // its next piece: the run's j-th (run_ids_)
        std::size_t first_release = 0;    // its next place in released_
        int choice = 0;                   // its index in the record
        std::uint64_t live = 0;           // pieces live as the record counts them when it commits
        int agent = -1;                   // whose
        int clip_id = -1;                 // the clip taken's piece
        std::int64_t clip_f1 = 0;         // the end of its box
        std::int64_t end = 0;             // the frame the clip taken ends
        bool settles = false;             // arrives for good (Policy::settled)
        std::int8_t wait = -1;            // waits from `end` on (1), no longer (0), unchanged (-1)
    };
    void commit_run(std::size_t from, std::size_t to);
    void count_commit(std::size_t i, Commit& out) const;
    void lay_out(std::size_t from, std::size_t to);
    void apply_commit(std::size_t i, Commit& at, CrowdSummary& tally);
    void list_commits(std::size_t from, std::size_t to, std::size_t part, std::size_t parts);
    void finish_commit(std::size_t i, const Commit& at);
    int place_piece(Piece piece, std::size_t j);
    void reserve(int agent, int choice, const Plan& plan, Commit& at);
    void record_plan(const Choice& c, ChoicePoint& cp) const;
    void note_waiting(const Choice& c, Agent& a, Commit& at) const;
    template <class Take>
    void hand_over(ChoicePoint& cp, Take&& take) const;
    void release(int id);
    void flush();
    void log_queries(const Choice& c, int choice);
    void fill_samples();
    // A streamed run (CrowdOptions::sink; frame_stream.cpp): its frames go out as they become final.
    void start_stream();
    CrowdRun finish_stream(std::chrono::steady_clock::time_point start, const std::function<void(double)>& progress);

    const MotionGraph& g_;
    const std::vector<ClipOutline> outlines_;
    const NarrowPhase& narrow_;
    const CrowdOptions& o_;
    const EscapeTable escapes_;
    const std::unique_ptr<Policy> policy_;
    const double hold_clearance_;        // metres held ground keeps from the solids (CrowdState)
    const std::vector<Polygon> solids_;  // none when the policy does not avoid
    const BroadPhase solid_grid_;
    util::WorkerPool pool_;
    BroadPhase broad_;               // pieces live now
    std::size_t pending_ = 0;        // pieces staged in broad_ since the last flush
    std::vector<int> released_;      // released in this frame, still in broad_
    std::size_t released_held_ = 0;  // how many of released_ broad_ holds
    std::size_t flushed_held_ = 0;   // how many of those the live count (commit) leaves out
    // The boxes a position's first plan takes and releases: found_[worker][begin, end).
    struct BoxSpan {
        int worker;
        std::size_t begin, end;
    };
    std::vector<std::vector<SpaceTimeBox>> found_;  // per worker: the boxes it found
    std::vector<BoxSpan> spans_;                    // per position: its boxes in found_
    BatchGrid chosen_;                              // the same, by position
    std::vector<int> touched_;    // per position: the last one before whose first plan may change it, or -1
    std::vector<int> seen_;       // per position: the positions committed when last evaluated
    std::vector<char> reroutes_;  // per position: its plan reroutes other agents (commits alone)
    std::vector<char> current_;   // per position: current(), as foresee() worked it out ahead of the commits
    std::vector<std::optional<SpaceTimeBox>> bounds_;  // per position: the union of what it queried
    std::vector<std::size_t> round_;                   // scratch: the positions evaluated again together
    BatchGrid moved_;  // boxes of the current batch's plans chosen again on re-evaluation, once committed
    std::vector<SpaceTimeBox> boxes_;    // scratch: one choice point's boxes
    std::vector<Commit> commits_;        // by batch position: what each commit adds and where it goes
    std::vector<int> run_ids_;           // the ids its pieces take, in commit order
    std::size_t run_pending_ = 0;        // where its pieces start among the staged ones
    std::int64_t run_seq_ = 0;           // the Piece::seq of its first piece
    std::vector<CrowdSummary> tallies_;  // per worker: the counts of the commits it applied
    std::vector<Agent> agents_;
    std::vector<Piece> pieces_;                       // by broad-phase id
    std::int64_t placed_ = 0;                         // pieces placed so far (the next Piece::seq)
    std::vector<int> unused_;                         // ids out of the broad phase, to reuse
    std::vector<int> left_;                           // ids released in this frame, unused from the next
    std::vector<std::vector<int>> ending_;            // per frame: ids of the committed clips ending then
    std::int64_t expired_until_ = 0;                  // ending_ below it went to unused_
    std::vector<std::vector<int>> due_;               // per frame: agents at a choice point
    std::vector<Choice> slots_;                       // one per choice point of a batch, reused
    BroadPhase waiting_;                              // agents that wait (give_way.h): their ground, by id
    std::vector<std::array<double, 2>> waiting_at_;   // per agent: where it waits
    std::vector<std::pair<int, bool>> wait_changes_;  // this frame's (agent, waits), applied after it
    std::vector<char> in_waiting_;                    // per agent: in waiting_
    CrowdRun out_;
    std::optional<FrameStream> stream_;
};

}  // namespace mobb::crowd
