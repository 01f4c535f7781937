// What `mobb crowd` prints of a run and the record keeps (CrowdSummary, crowd.h).
#include <sstream>

#include <nlohmann/json.hpp>

#include "mobb/crowd/sim/crowd.h"

namespace mobb::crowd {

namespace {

double per(std::uint64_t x, std::uint64_t n) { return n ? double(x) / double(n) : 0.0; }

}  // namespace

double CrowdSummary::cd_us_per_agent_second() const {
    const double n = double(agents) * simulated_seconds;
    return n > 0 ? cd_seconds * 1e6 / n : 0.0;
}

std::string summary_json(const CrowdSummary& s) {
    nlohmann::ordered_json j;
    j["choice_points"] = s.choice_points;
    j["candidates"] = s.candidates;
    j["queries"] = s.queries;
    j["positive_queries"] = s.hits;
    j["mean_tests2d"] = per(s.tests2d, s.queries);
    j["mean_tests3d"] = per(s.tests3d, s.queries);
    j["mean_samples"] = per(s.samples, s.queries);
    j["root_rejected_share"] = per(s.root_rejected, s.queries);
    j["time_overlapping_pairs"] = s.time_pairs;
    j["pairs_pruned"] = s.pruned;
    j["escapes"] = s.escapes;
    j["right_of_way"] = s.right_of_way;
    j["reroutes"] = s.reroutes;
    j["fallbacks"] = s.fallbacks;
    j["fallbacks_meeting_solids"] = s.fallbacks_meeting_solids;
    j["contacts"] = s.contacts;
    j["contacts_outside_fallbacks"] = s.contacts_unexcused;
    j["reevaluated"] = s.reevaluated;
    return j.dump();
}

std::string summary_text(const CrowdSummary& s) {
    std::ostringstream out;
    out << "choice points            " << s.choice_points << " (" << s.candidates << " candidates)\n"
        << "queries                  " << s.queries << " (" << s.hits << " positive)\n"
        << "mean tests per query     2D " << per(s.tests2d, s.queries) << ", 3D " << per(s.tests3d, s.queries)
        << ", samples " << per(s.samples, s.queries) << "\n"
        << "rejected at the root     " << 100.0 * per(s.root_rejected, s.queries) << " %\n"
        << "pairs pruned (broad)     " << s.pruned << " of " << s.time_pairs << " overlapping in time\n"
        << "escapes taken            " << s.escapes << " (" << 100.0 * per(s.escapes, s.choice_points)
        << " % of choice points)\n"
        << "right of way             " << s.right_of_way << " (" << s.reroutes << " plans of others gave way)\n"
        << "fallbacks                " << s.fallbacks << " (" << 100.0 * per(s.fallbacks, s.choice_points) << " %, "
        << s.fallbacks_meeting_solids << " meeting a wall or an obstacle)\n"
        << "contacts (frame check)   " << s.contacts << " agent-pair frames, " << s.contacts_unexcused
        << " outside fallbacks\n"
        << "re-evaluated choices     " << s.reevaluated << " (a commit earlier in the frame was near)\n"
        << "simulation time          " << s.seconds << " s (" << s.threads << " threads)\n"
        << "collision detection      " << s.cd_seconds << " s, " << s.cd_us_per_agent_second()
        << " us per agent per simulated s\n"
        << "parallel steps           " << s.parallel_steps
        << " (the frames' steps handed to the worker threads; none on one thread)\n";
    return out.str();
}

}  // namespace mobb::crowd
