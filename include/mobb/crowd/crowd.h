// Graph-driven crowd simulation with space-time collision queries at choice points (paper section 5).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/core/query.h"
#include "mobb/core/tree.h"
#include "mobb/crowd/motion_graph.h"
#include "mobb/crowd/record.h"

namespace mobb::crowd {

/// How an agent picks its next clip at a choice point.
enum class Selection {
    Avoid,   ///< first candidate (random order) inside the world and free of collisions; else fewest collisions
    Random,  ///< a random successor, but every candidate's queries still run (the paper's timing experiment)
};
const char* to_string(Selection s);
Selection parse_selection(const std::string& name);  ///< "avoid" | "random"; throws std::invalid_argument

struct CrowdOptions {
    int agents = 100;
    double width = 30, height = 40;  ///< world rectangle [0, W] x [0, H], metres
    double seconds = 120;            ///< simulated; frames = round(seconds / dt)
    std::uint64_t seed = 1;
    Selection select = Selection::Avoid;
    double cell = 4.0;         ///< broad-phase grid cell, metres
    bool log_queries = false;  ///< keep every narrow-phase query (for replays by the benchmarks)
    /// Worker threads for the choice points (>= 1; the calling thread is one of them). The record, the
    /// logged queries and every counter are the same for any count; only the times differ.
    int threads = 1;
};

/// One narrow-phase query of a run: candidate clip a at pa against committed clip b at pb.
struct LoggedQuery {
    int choice = 0, candidate = 0;  ///< indices into Record::choices and its candidates
    int clip_a = 0, clip_b = 0;
    Placement pa, pb;
    bool hit = false;
};

/// What `mobb crowd` prints. Means are per narrow-phase query.
struct CrowdSummary {
    std::uint64_t choice_points = 0, candidates = 0, queries = 0, hits = 0;
    std::uint64_t tests2d = 0, tests3d = 0, samples = 0;
    /// Queries whose only box test (if any) was the roots' and that tested no samples.
    std::uint64_t root_rejected = 0;
    std::uint64_t time_pairs = 0;                        ///< (candidate, committed clip) pairs overlapping in time
    std::uint64_t pruned = 0;                            ///< of those, skipped by the broad phase
    std::uint64_t fallbacks = 0, outside = 0;            ///< fallback clips taken; of them, clips leaving the world
    std::uint64_t contacts = 0, contacts_unexcused = 0;  ///< frame-by-frame contacts (agent pairs x frames)
    std::uint64_t reevaluated = 0;  ///< choice points evaluated again: a commit earlier in their frame was near
    std::uint64_t agents = 0;       ///< the run's agents
    double simulated_seconds = 0;   ///< frames * dt
    int threads = 1;                ///< worker threads of the run
    double seconds = 0;             ///< wall time of the simulation (without the record check)
    /// Wall time of collision detection in it: the frames' choice points (candidate placement, broad
    /// phase, narrow-phase queries, re-evaluations) and their commits to the broad phase.
    double cd_seconds = 0;

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
};

/// One tree per graph clip, built once.
std::vector<Tree> build_trees(const MotionGraph& graph, const TreeOptions& options);

/// Runs the crowd (paper section 5). Deterministic for a seed, whatever options.threads. Agents start
/// at random positions at least 2 r_max apart (r_max: the largest r of the graph) and r_max from the
/// walls, with random headings; each first choice point offers the successors of a random clip. The
/// random draws of a choice point (candidate order, first clip, random pick) come from its own stream
/// of (seed, agent, frame). Choice points take effect in order of frame, then agent: those of one frame
/// are evaluated in parallel against the clips committed before that frame, then committed in agent
/// order, and one whose candidates overlap a clip committed earlier in its frame is evaluated again
/// first, so the outcome equals one-by-one evaluation. A candidate is tested against the committed
/// clips of the other agents whose space-time boxes overlap its own (BroadPhase; a box spans the
/// clip's frames and its root positions padded by its largest radius r); committed clips
/// checked at every commit guarantee, outside fallbacks, no contact at any frame. Throws
/// std::invalid_argument for bad options (threads < 1 included), a graph clip without successors or
/// a world too small for the agents. `progress` (may be empty) receives the simulated fraction done.
CrowdRun run_crowd(const MotionGraph& graph, const std::vector<Tree>& trees, const CrowdOptions& options,
                   const std::function<void(double)>& progress = {});

}  // namespace mobb::crowd
