// A streamed run's ends (CrowdOptions::sink), apart from the simulation's steps in crowd.cpp: the stream
// starts once the agents are placed and closes after the last frame, with the run's contacts and metrics.
#include "sim/simulation.h"

namespace mobb::crowd {

void Simulation::start_stream() {
    Record& r = out_.record;
    for (std::size_t a = 0; a < agents_.size(); ++a) {
        r.tracks[a].goals = agents_[a].goals;
        r.tracks[a].at_goal = agents_[a].at_goal;
    }
    stream_.emplace(g_, r, *o_.sink, o_.goal_radius);
}

CrowdRun Simulation::finish_stream(std::chrono::steady_clock::time_point start,
                                   const std::function<void(double)>& progress) {
    stream_->finish();
    for (std::size_t a = 0; a < agents_.size(); ++a) out_.record.tracks[a].left_frame = agents_[a].left_frame;
    CrowdSummary& s = out_.summary;
    // The check and the metrics ran as the frames came: their time is not the simulation's.
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - stream_->seconds();
    s.contacts = stream_->contacts();
    s.contacts_unexcused = s.contacts - stream_->contacts_excused();
    out_.metrics = stream_->metrics(s.choice_points, s.fallbacks);
    if (progress) progress(1.0);
    return std::move(out_);
}

}  // namespace mobb::crowd
