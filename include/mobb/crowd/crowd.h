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
    double width = 30, height = 40;   ///< world rectangle [0, W] x [0, H], metres
    double seconds = 120;             ///< simulated; frames = round(seconds / dt)
    std::uint64_t seed = 1;
    Selection select = Selection::Avoid;
    double cell = 4.0;                ///< broad-phase grid cell, metres
    bool log_queries = false;         ///< keep every narrow-phase query (for replays by the benchmarks)
    int threads = 1;                  ///< worker threads for choice points; the record is the same for any count
};

/// One narrow-phase query of a run: candidate clip a at pa against committed clip b at pb.
struct LoggedQuery {
    int choice = 0, candidate = 0;    ///< indices into Record::choices and its candidates
    int clip_a = 0, clip_b = 0;
    Placement pa, pb;
    bool hit = false;
};

/// What `mobb crowd` prints. Means are per narrow-phase query.
struct CrowdSummary {
    std::uint64_t choice_points = 0, candidates = 0, queries = 0, hits = 0;
    std::uint64_t tests2d = 0, tests3d = 0, samples = 0;
    std::uint64_t root_rejected = 0;   ///< queries whose only box test (if any) was the roots' and that tested no samples
    std::uint64_t time_pairs = 0;      ///< (candidate, committed clip) pairs overlapping in time
    std::uint64_t pruned = 0;          ///< of those, skipped by the broad phase
    std::uint64_t fallbacks = 0, outside = 0;  ///< fallback clips taken; of them, clips leaving the world
    std::uint64_t contacts = 0, contacts_unexcused = 0;  ///< frame-by-frame contacts (agent pairs x frames)
    double seconds = 0;                ///< wall time of the simulation (without the record check)
    double cd_seconds = 0;             ///< wall time of collision detection in it (broad + narrow phase)
};
std::string summary_json(const CrowdSummary& s);
std::string summary_text(const CrowdSummary& s);

struct CrowdRun {
    Record record;
    CrowdSummary summary;
    std::vector<LoggedQuery> queries;  ///< when options.log_queries
};

/// One tree per graph clip, built once.
std::vector<Tree> build_trees(const MotionGraph& graph, const TreeOptions& options);

/// Runs the crowd. Deterministic for a seed. Agents start at random positions at least 2 r_max apart
/// (r_max: the largest r of the graph) and r_max from the walls, with random headings; each first
/// choice point offers the successors of a random clip. Choice points are taken in order of frame,
/// then agent. A candidate is tested against the committed clips of the other agents whose space-time
/// boxes overlap its own (BroadPhase); committed clips checked at every commit guarantee, outside
/// fallbacks, no contact at any frame. Throws std::invalid_argument for bad options or a world too
/// small for the agents. `progress` (may be empty) receives the simulated fraction done.
CrowdRun run_crowd(const MotionGraph& graph, const std::vector<Tree>& trees, const CrowdOptions& options,
                   const std::function<void(double)>& progress = {});

}  // namespace mobb::crowd
