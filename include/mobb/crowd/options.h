// The options of a crowd run (run_crowd, sim/crowd.h): its agents, world, policy, rules and record.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/crowd/policy/policy.h"
#include "mobb/crowd/record/record.h"
#include "mobb/crowd/tuning.h"
#include "mobb/crowd/world/world.h"

namespace mobb::crowd {

/// An agent placed by a scenario.
struct AgentSpec {
    Placement start;                           ///< x, y (metres), heading theta (radians); t0 unused
    double start_time = 0;                     ///< seconds: it stands at its start until then
    std::vector<std::array<double, 2>> goals;  ///< metres, reached in turn (within goal_radius); empty: wanders
    AtGoal at_goal = AtGoal::Stay;             ///< at the last goal: stand there, or leave the run
};

struct CrowdOptions {
    int agents = 100;      ///< placed at random when `placed` is empty
    World world;           ///< default [0, 30] x [0, 40], walled
    double seconds = 120;  ///< simulated; frames = round(seconds / dt)
    std::uint64_t seed = 1;
    Selection select = Selection::Wander;
    double cell = 4.0;         ///< broad-phase grid cell, metres
    bool log_queries = false;  ///< keep every narrow-phase query (for replays by the benchmarks)
    /// Keep each candidate's queries (Candidate::against) in the record, for the viewer and the record
    /// digests; off, the record's choice points (streamed ones too) keep only their counts, not their
    /// candidates (the runs are otherwise the same). `mobb crowd` sets it for a JSON record, and for an
    /// HDF5 one with --record-candidates (keeps_candidates, record_file.h).
    bool record_queries = true;
    /// When set, the run streams: its choice points (candidates included with record_queries), clips and
    /// frames go there as they are committed and become final (RecordSink), the contact check and the
    /// metrics run on the frames as they come (CrowdRun::metrics), and the run keeps none of them - the
    /// returned record has only its header and its tracks' goals, at_goal and left_frame. Memory then does
    /// not grow with the run's length.
    RecordSink* sink = nullptr;
    /// Worker threads for the choice points (>= 1; the calling thread is one of them). The record, the
    /// logged queries and every counter are the same for any count; only the times differ.
    int threads = 1;
    /// Choice points evaluated at once, at most (>= 1). A frame with more - the first, where every agent
    /// chooses - runs them as consecutive batches of this many: the outcome is the same (each choice
    /// point's plan is that of evaluating it after the commits before it, in agent order), the slots and
    /// lists a batch grows stay this size. Only time and memory depend on it.
    int max_batch = 4096;
    std::vector<AgentSpec> placed;  ///< the agents of a scenario (then `agents` is ignored)
    /// Metres: a goal agent this close to its goal has reached it - it heads for the next, leaves (once
    /// it has played a clip), or stops there.
    double goal_radius = 1.0;
    /// The rules' numbers and switches (tuning.h): the look-ahead of goal agents, the right of way,
    /// giving way, the standing gap.
    CrowdTuning tuning;
};

}  // namespace mobb::crowd
