// A run's frames as they become final (CrowdOptions::sink): a frame is final once every agent's committed
// clips cover it, which at the start of frame f holds for every frame before f (an agent's next choice
// point is at the end of its last clip). The stream keeps each agent's clips until their frames are out,
// puts the agents' disks there a block of frames at a time, as fill_samples (crowd.cpp) puts them in a
// whole record, and runs the frame-by-frame contact check and the metrics on each block before handing it
// to the sink. Private to src/crowd.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "metrics/metrics_stream.h"
#include "mobb/core/path.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/record/record.h"
#include "mobb/util/worker_pool.h"
#include "record/frame_blocks.h"
#include "record/frame_grid.h"

namespace mobb::crowd {

/// Frames the stream puts in place and measures at a time: whole blocks, up to 32 frames or 8 M disks
/// (256 MB), at least one block. Each agent's track and metrics are then read once for many frames: at a
/// million agents, where a block is one frame, reading them frame by frame was most of the stream's time.
std::int64_t group_frames(std::size_t agents);

class FrameStream {
public:
    /// `header`: the run's header and its tracks' goals (RecordSink::begin), kept by reference.
    FrameStream(const MotionGraph& graph, const Record& header, RecordSink& sink, double goal_radius);

    /// The agents' disks and metrics of each block are then found by `pool`'s workers (one thread without).
    void share(util::WorkerPool& pool) { pool_ = &pool; }
    /// A clip agent `agent` committed, kept until its frames are out (the sink gets it from the
    /// simulation, in commit order). Agents apart, from any thread.
    void clip(int agent, const PlacedClip& clip);
    /// The agent left the run at `frame`: its disks are NaN from then on.
    void left(int agent, std::int64_t frame);
    /// Frames before `frame` are final: whole groups of them go out (group_frames), block by block.
    void until(std::int64_t frame);
    /// After the run's last frame: the rest goes out.
    void finish();

    std::uint64_t contacts() const { return contacts_; }
    std::uint64_t contacts_excused() const { return excused_; }
    CrowdMetrics metrics(std::uint64_t choice_points, std::uint64_t fallbacks) {
        return metrics_.finish(choice_points, fallbacks);
    }
    double seconds() const { return seconds_; }  ///< wall time spent in the stream so far

private:
    struct Track {
        std::vector<PlacedClip> clips;  // from the one playing at the next frame out
        std::size_t k = 0;              // the one playing
        Rigid2 m;                       // its placement
        std::int64_t left = std::numeric_limits<std::int64_t>::max();
    };
    void emit(std::int64_t count);
    void place(std::int64_t count, util::WorkerPool& pool);
    void find_contacts(std::int64_t count, util::WorkerPool& pool);
    void sweep_window(std::int64_t first, std::int64_t frames, util::WorkerPool& pool);
    void test_pair(int a, int b, std::int64_t first, std::int64_t frames, std::vector<Contact>& out) const;
    void count_contacts(std::int64_t frame, const std::array<double, 4>* disks, const char* fallback,
                        std::vector<Contact>& found);

    const MotionGraph& g_;
    const Record& header_;
    RecordSink& sink_;
    MetricsStream metrics_;
    std::vector<Track> tracks_;
    std::int64_t next_ = 0;  // the first frame not out yet
    util::WorkerPool* pool_ = nullptr;
    const std::int64_t block_;
    const std::int64_t group_;                  // frames emitted at a time: whole blocks
    std::vector<std::array<double, 4>> disks_;  // a group, frame-major
    std::vector<std::array<double, 2>> roots_;  // the same frames' roots, for disks centred on the body
    std::vector<char> fallback_;                // per disk: a fallback clip plays then
    // The contact check of a window of frames: per agent the disk about where its disks lie, whose overlaps
    // are the pairs worth testing frame by frame.
    std::vector<FrameGrid::Disk> swept_;   // per agent; r < 0 when it is in no frame of the window
    std::vector<FrameGrid::Disk> in_run_;  // the swept disks of the agents in the run
    FrameGrid grid_;
    std::vector<std::vector<Contact>> pairs_;  // per worker: the contacts its pairs had
    std::vector<std::vector<Contact>> found_;  // per frame of the group: its contacts
    std::uint64_t contacts_ = 0, excused_ = 0;
    double seconds_ = 0;
};

}  // namespace mobb::crowd
