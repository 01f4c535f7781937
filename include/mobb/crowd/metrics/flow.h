// Flow through a line: when each agent first crosses it, and the steady rate (issue 45's door target:
// SteerSuite's bottleneck-evacuation read between its 10th and 90th percentile crossing; people pass about
// 1.9 persons/s through a 1 m door - Seyfried et al. 2009 - with a 1.3 s headway per lane in a bottleneck -
// Hoogendoorn and Daamen 2005). Read from a record's samples (disk centres), window by window, so that a
// record too large for memory is read in parts.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "mobb/crowd/record/record_file.h"

namespace mobb::crowd {

/// The line x = at (axis 0) or y = at (axis 1), metres.
struct FlowLine {
    int axis = 0;
    double at = 0;
};

/// "x=5", "y=-2.5" (spaces allowed round "="). Throws std::invalid_argument naming the text otherwise.
FlowLine parse_flow_line(const std::string& text);

struct Crossing {
    std::size_t agent = 0;
    double time = 0;  ///< seconds: between the two frames either side, linearly
    int way = 0;      ///< +1: toward a larger coordinate, -1: toward a smaller one
};

/// Each agent's first crossing of the line, from windows of every agent given in frame order (each
/// window starting where the one before ended, or overlapping it). An agent's sample at a frame is
/// its disk's centre; a sample after the agent left the run (NaN) ends its track.
class FlowCounter {
public:
    FlowCounter(FlowLine line, std::size_t agents);
    void add(const SampleWindow& window);
    /// The crossings so far, by time (then agent).
    std::vector<Crossing> crossings() const;

private:
    FlowLine line_;
    /// Per agent: its coordinate at the frame seen_ (NaN once seen: done - it crossed or left the run).
    std::vector<double> last_;
    std::vector<std::int64_t> seen_;  ///< per agent: the frame of last_ (-1: none yet)
    std::vector<Crossing> crossed_;
};

struct Flow {
    std::size_t crossings = 0, forward = 0, backward = 0;  ///< forward: toward a larger coordinate
    double first = 0, last = 0;                            ///< seconds: the first and last crossing
    /// Agents per second between the 10th and 90th percentile crossing (index round(0.1 (n - 1)) and
    /// round(0.9 (n - 1)) of the n sorted times); 0 with fewer than 3 crossings or none apart in time.
    double rate = 0;
    double rate_from = 0, rate_to = 0;  ///< seconds: those two crossings
    double median_headway = 0;          ///< seconds between consecutive crossings (0 with fewer than 2)
};

/// The flow of `crossings` (by time, as FlowCounter::crossings gives them).
Flow flow_of(const std::vector<Crossing>& crossings);

}  // namespace mobb::crowd
