// The escape an agent keeps open: every clip it commits to comes with a way to stop - a short chain of
// successor clips ending in an idle clip (ClipKind::Idle: standing, looping in place) - and the ground
// where it would then stand, held for as long as it does (a disk in space-time from then on). Other
// agents plan around both, so an agent can always fall back on its own escape instead of walking into
// someone (Lau and Kuffner's behaviour planning keeps such a safe option; Snap-Together Motion's hub
// poses make the stops reachable).
#pragma once
#include <array>
#include <vector>

#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/tuning.h"

namespace mobb::crowd {

struct EscapeTable {
    std::vector<ClipKind> kind;  ///< per clip
    std::vector<char> in_place;  ///< per clip: InPlace or Idle
    /// Per clip: from its start to its exit at CrowdTuning::moving_speed or faster (an agent playing it
    /// is not waiting). An agent that played none for a while has the right of way (rules/right_of_way.h).
    std::vector<char> moves;
    std::vector<double> footprint;  ///< per clip: max over samples of |p_i - p_0| + r_i
    /// Per clip: successor chains c1..ck, ck idle (k = 1 when a successor already is), the shortest first,
    /// then one clip longer, at most EscapeTuning::routes of them; none when an idle clip is more
    /// than EscapeTuning::steps clips away.
    std::vector<std::vector<std::vector<int>>> routes;
    /// Per clip, per route: where the route's held ground is, in the clip's own frame (metres: the clip
    /// placed at the origin facing +x), so a choice point places it without chaining the route.
    std::vector<std::vector<std::array<double, 2>>> ends;
    double hold_radius = 0;  ///< hold_of() the largest idle clip: any idle clip fits
    /// How far held ground may come to walls and obstacles: room for any idle clip plus
    /// EscapeTuning::wall_margin, so an agent that stops can stand there (where its policy stops near
    /// walls: CrowdState::hold_clearance).
    double stand_clearance = 0;
    /// How far a start stays from walls and obstacles: room for any clip in place (turning on the spot)
    /// plus EscapeTuning::wall_margin, so an agent can set off in every direction.
    double turn_clearance = 0;

    /// The held ground's radius for idle clip `idle`: its footprint (it loops exactly in place), a
    /// micrometre wider so that placing it cannot round a disk out.
    double hold_of(int idle) const { return footprint[std::size_t(idle)] * (1 + 1e-9) + 1e-6; }

    static constexpr int kMaxRoutes = 32;  ///< a choice point marks a clip's routes in 32 bits

    /// With CrowdTuning's moving_speed and escape (steps, routes, wall_margin). Throws
    /// std::invalid_argument when the graph has no idle clip or escape.routes > kMaxRoutes.
    static EscapeTable build(const MotionGraph& graph, const CrowdTuning& tuning = {});
};

}  // namespace mobb::crowd
