// Graph-driven crowd simulation with space-time collision queries at choice points (paper section 5).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/core/query.h"
#include "mobb/core/tree.h"
#include "mobb/crowd/collision/narrow_phase.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/options.h"
#include "mobb/crowd/record/record.h"

namespace mobb::crowd {

/// What `mobb crowd` prints. Means are per narrow-phase query.
struct CrowdSummary {
    std::uint64_t choice_points = 0, candidates = 0, queries = 0, hits = 0;
    std::uint64_t tests2d = 0, tests3d = 0, samples = 0;
    /// Queries whose only box test (if any) was the roots' and that tested no samples.
    std::uint64_t root_rejected = 0;
    std::uint64_t time_pairs = 0;                        ///< (candidate, committed piece) pairs overlapping in time
    std::uint64_t pruned = 0;                            ///< of those, skipped by the broad phase
    std::uint64_t escapes = 0;                           ///< choice points where the agent took its own escape
    std::uint64_t right_of_way = 0;                      ///< choice points taken by the right of way (choice.h)
    std::uint64_t reroutes = 0;                          ///< other agents' plans that gave way to them
    std::uint64_t fallbacks = 0;                         ///< fallback clips taken
    std::uint64_t fallbacks_meeting_solids = 0;          ///< of them, clips meeting a wall or an obstacle
    std::uint64_t contacts = 0, contacts_unexcused = 0;  ///< frame-by-frame contacts (agent pairs x frames)
    std::uint64_t reevaluated = 0;  ///< choice points evaluated again: a commit earlier in their frame was near
    std::uint64_t agents = 0;       ///< the run's agents
    double simulated_seconds = 0;   ///< frames * dt
    int threads = 1;                ///< worker threads of the run
    double seconds = 0;             ///< wall time of the simulation (without the record check)
    /// Wall time of collision detection in it: the frames' choice points (candidate placement, broad
    /// phase, narrow-phase queries, re-evaluations) and their commits to the broad phase.
    double cd_seconds = 0;
    /// Steps of the frames' choice points handed to the worker threads (WorkerPool::steps): each a wake
    /// and a wait on every thread, a cost that grows with their number. The same for any thread count from
    /// 2 (loops split by the thread count split in more than one task from there); none on one thread.
    std::uint64_t parallel_steps = 0;

    /// Collision detection per agent per simulated second, microseconds (0 for an empty run).
    double cd_us_per_agent_second() const;
};
/// The summary as one JSON object (the record's "summary": counts only, so a record is the same for
/// any run and thread count), and as `mobb crowd` prints it (with threads and wall times).
std::string summary_json(const CrowdSummary& s);
std::string summary_text(const CrowdSummary& s);

struct CrowdRun {
    Record record;
    CrowdSummary summary;
    std::vector<LoggedQuery> queries;  ///< when options.log_queries
    /// A streamed run's metrics (options.sink set), equal to crowd_metrics of its whole record.
    std::optional<CrowdMetrics> metrics;
};

/// One tree per graph clip, built once.
std::vector<Tree> build_trees(const MotionGraph& graph, const TreeOptions& options);

/// Runs the crowd (paper section 5). Deterministic for a seed, whatever options.threads.
///
/// Agents: a scenario's (options.placed), or options.agents at random positions inside the world, apart
/// and clear of the obstacles, with random headings; each first choice point offers the successors of a
/// random clip. The random draws of a choice point (candidate order, first clip, random pick) come from
/// its own stream of (seed, agent, frame); the policy (policy.h) then orders the candidates.
///
/// Avoid and goal: a candidate is taken only when its plan is free - the clip, the clips that would stop
/// the agent after it and the ground it would then hold (escape.h) - of every other agent's plan, of the
/// obstacles and of the world's walls; the first such candidate in the policy's order is taken, and when
/// there is none the agent takes its own escape, which the others planned around. The rules that
/// order and pass candidates - the right of way (after Okumura et al.'s PIBT, 2019), giving way, the
/// standing gap, the look-ahead of goal agents - each have a file of their own in src/crowd and their
/// numbers and switches in CrowdTuning (tuning.h). So, outside fallbacks (no escape left), no two agents
/// ever touch and no disk crosses a wall, whichever rules are on. Goal agents head for their goals in
/// turn and stay at the last or leave the run there (AgentSpec). Random (the policy that does not
/// avoid, Policy::avoids): a random successor; every candidate's queries still run; no escapes, no
/// walls (the paper's timing workload).
///
/// Choice points take effect in order of frame, then agent: those of one frame are evaluated in
/// parallel against the state at the start of the frame, then committed in agent order, and one that a
/// commit earlier in its frame could change is evaluated again first, so the outcome equals one-by-one
/// evaluation. Throws std::invalid_argument for bad options (threads < 1 included), a graph clip without
/// successors or without a clip in place, or a world too small for the agents. `progress` (may be empty)
/// receives the simulated fraction done.
CrowdRun run_crowd(const MotionGraph& graph, const NarrowPhase& narrow, const CrowdOptions& options,
                   const std::function<void(double)>& progress = {});

}  // namespace mobb::crowd
