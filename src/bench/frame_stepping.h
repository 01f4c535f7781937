// The baseline a crowd simulator without space-time bounds would use: step a candidate clip frame by
// frame and test its disk against the other agents' disks at that frame, found through a uniform grid.
#pragma once
#include <cstdint>

#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/record/record.h"

namespace mobb::bench {

struct FrameSteppingResult {
    std::uint64_t candidates = 0;     ///< candidate clips checked
    std::uint64_t positive = 0;       ///< candidates touching a committed agent at some frame
    std::uint64_t disk_tests = 0;     ///< disk-disk tests
    std::uint64_t disagreements = 0;  ///< candidates whose answer differs from the record's queries:
    std::uint64_t only_queries = 0;   ///< of them, positive by the queries only (time intervals that
                                      ///< overlap by rounding between neighbouring frames: conservative)
    std::uint64_t only_stepping = 0;  ///< positive by frame stepping only (would be a bug)
    double build_seconds = 0;         ///< building one sorted grid per frame (shared by all candidates)
    double check_seconds = 0;         ///< stepping the candidates
};

/// Re-checks every candidate of every choice point of `record` (a run of `graph`): at each of its
/// frames, against every other agent whose clip then was committed before that choice point, exiting
/// at the first contact. The record's candidates must carry full hit counts (random selection runs
/// every query), for the agreement count.
FrameSteppingResult frame_stepping(const crowd::MotionGraph& graph, const crowd::Record& record);

}  // namespace mobb::bench
