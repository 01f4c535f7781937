// The metrics of metrics.h on a run's frames as they complete (FrameStream, frame_stream.h), one frame at
// a time, with a fixed state per agent (its last frames for the idle window and SteerSuite's resampling,
// its sums), so nothing grows with the run's length. Each number is summed in the order crowd_metrics
// sums it on the whole record, so the two agree to the last bit (tests/crowd/record/record_stream_test.cpp).
// Private to src/crowd.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "mobb/crowd/metrics/metrics.h"
#include "mobb/util/worker_pool.h"

namespace mobb::crowd {

class MetricsStream {
public:
    /// `header`: the run's dt, frames, world and its tracks' goals; goal_radius in metres.
    MetricsStream(const Record& header, const MotionGraph& graph, double goal_radius);

    /// The contacts of frame `frame` (frame_contacts' order), frames in order from 0, and `disks` its
    /// every agent's disk [t, x, y, r] (NaN from the frame it left on).
    void contacts(std::int64_t frame, const std::array<double, 4>* disks, const Contact* contacts, std::size_t count);
    /// Frames first .. first + count - 1, once contacts() had them: every agent's disks, frame-major
    /// (disks[k * agents + a] at frame first + k), and its root [x, y] there the same way where the graph
    /// centres its disks on the body (null: the disks' centres are the roots). The agents are measured in
    /// parallel by `pool`'s workers: each one's state is its own, and the counts they share are integers
    /// (summed in any order).
    void frames(std::int64_t first, std::int64_t count, const std::array<double, 4>* disks,
                const std::array<double, 2>* roots, util::WorkerPool& pool);
    /// After the run's last frame: the metrics, with the run's choice points and fallbacks (CrowdSummary).
    CrowdMetrics finish(std::uint64_t choice_points, std::uint64_t fallbacks);

private:
    struct Track {
        std::int64_t n = 0;                // samples so far
        bool ended = false, left = false;  // its track ended; before the run's (it left)
        std::array<double, 2> start{};
        double length = 0, to_goal = 0;
        std::size_t goal = 0;       // the goal it heads for
        std::int64_t reached = -1;  // the frame it came within the radius of its last goal
        std::int64_t idle_next = 0, run = 0, longest = 0;
        bool idle_done = false;
        int effort_next = 0;  // SteerSuite's next 20 Hz step
        bool effort_done = false;
        double energy = 0, acceleration = 0, vx0 = 0, vy0 = 0;
        std::int64_t last_solid = -2;  // the last frame its disk met a solid
        int collisions = 0;            // episodes (metrics.cpp's `episodes`)
    };

    struct Counts {  // what the agents add to the crowd's counts, one per worker
        std::uint64_t samples_outside = 0, obstacle_contacts = 0, idle = 0;
    };

    void sample(std::size_t a, std::int64_t f, const std::array<double, 4>& s, const std::array<double, 2>& root,
                Counts& counts);
    void solid(std::size_t a, std::int64_t f, const std::array<double, 4>& s, Counts& counts);
    void idle(std::size_t a, Track& t, Counts& counts);
    void effort(std::size_t a, Track& t);
    void end(std::size_t a, Counts& counts);
    void add(const Counts& counts);
    const std::array<double, 2>& at(std::size_t a, std::int64_t f) const {
        return ring_[a * ring_size_ + std::size_t(f) % ring_size_];
    }
    std::array<double, 2> at_time(std::size_t a, const Track& t, double time) const;

    const Record& header_;
    const double radius_;
    const std::int64_t half_;  // frames in half the idle window
    CrowdMetrics m_;
    std::vector<Polygon> solids_;
    std::vector<std::array<double, 4>> boxes_;
    std::vector<Track> tracks_;
    std::size_t ring_size_;
    std::vector<std::array<double, 2>> ring_;  // per agent its root's last ring_size_ positions
    std::uint64_t idle_ = 0;
    std::map<std::pair<int, int>, std::int64_t> last_contact_;  // pairs in contact at the last frame
};

}  // namespace mobb::crowd
