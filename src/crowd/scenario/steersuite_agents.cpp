// SteerSuite's agents as mobb's: starts given or drawn, checked as the crowd will check them and moved
// where a mobb agent has room; goals; the notes of what could not be mapped; the time limit.
#include <algorithm>
#include <cmath>

#include "mobb/core/angle.h"
#include "scenario/steersuite_importer.h"

namespace mobb::crowd::steersuite {

std::optional<std::array<double, 2>> Importer::random_start(const Box& region) {
    const World& w = s_.world;
    const Box r{std::max(region.x0, w.x0), std::max(region.y0, w.y0), std::min(region.x1, w.x1),
                std::min(region.y1, w.y1), ""};
    if (r.x0 > r.x1 || r.y0 > r.y1) return std::nullopt;
    for (int t = 0; t < kTries; ++t) {
        const double x = util::rounded(rng_.uniform(r.x0, r.x1), 2), y = util::rounded(rng_.uniform(r.y0, r.y1), 2);
        if (w.inside(x, y) && clear_of_solids(x, y, room_.wall_clearance) && starts_.clear(x, y))
            return std::array<double, 2>{x, y};
    }
    return std::nullopt;
}

// Anywhere in the world clear of the solids, and of other goals when there is room.
std::array<double, 2> Importer::random_goal() {
    const World& w = s_.world;
    std::array<double, 2> fallback{util::rounded((w.x0 + w.x1) / 2, 2), util::rounded((w.y0 + w.y1) / 2, 2)};
    bool found = false;
    for (int t = 0; t < kTries; ++t) {
        const double x = util::rounded(rng_.uniform(w.x0, w.x1), 2), y = util::rounded(rng_.uniform(w.y0, w.y1), 2);
        if (!clear_of_solids(x, y, room_.wall_clearance)) continue;
        if (goals_.clear(x, y)) return {x, y};
        if (!found) fallback = {x, y};
        found = true;
    }
    return fallback;
}

// The group's targets in turn, random ones drawn; false at the first outside the world (goals.back()).
bool Importer::goals_of(const Group& g, std::vector<std::array<double, 2>>& goals) {
    goals.clear();
    for (const Target& t : g.goals.targets) {
        goals.push_back(t.at.random ? random_goal() : std::array<double, 2>{t.at.x, t.at.y});
        drew_ = drew_ || t.at.random;
        if (!s_.world.inside(goals.back()[0], goals.back()[1])) return false;
    }
    return true;
}

// Why an agent cannot start at (x, y), as the crowd checks a start; "" when it can.
std::string Importer::misfit(double x, double y) const {
    if (!s_.world.inside(x, y)) return "starts outside the world";
    if (!clear_of_solids(x, y, room_.stand_clearance)) {
        const double d = solid_distance(x, y);
        return (d > 0 ? "starts " + num(d) + " m from a wall or an obstacle"
                      : std::string("starts inside an obstacle")) +
               "; mobb's agents need " + num(room_.stand_clearance) + " m to stand";
    }
    for (std::size_t k = 0; k < kept_starts_.size(); ++k) {
        const double d = std::hypot(kept_starts_[k][0] - x, kept_starts_[k][1] - y);
        if (d < 2 * room_.hold_radius)
            return "starts " + num(d) + " m from the agent at line " + std::to_string(kept_lines_[k]) +
                   "; two standing agents need " + num(2 * room_.hold_radius) + " m";
    }
    return "";
}

// The place nearest (x, y), within kMostMove, where an agent may start: on rings 1 cm apart, points 1 cm
// apart on each, to the centimetre; on the first ring where any fits, the nearest of those.
std::optional<std::array<double, 2>> Importer::nearest_fit(double x, double y) const {
    std::vector<const Polygon*> near;  // the solids within reach of any point tried
    for (const Polygon& p : world_solids_)
        if (box_gap(bounds(p), {x, y, x, y}) < kMostMove + room_.stand_clearance) near.push_back(&p);
    const auto fits = [&](double px, double py) {
        if (!s_.world.inside(px, py) || !starts_.clear(px, py)) return false;
        return std::none_of(near.begin(), near.end(),
                            [&](const Polygon* p) { return disk_overlaps(*p, px, py, room_.stand_clearance); });
    };
    constexpr double kStep = 0.01;
    std::optional<std::array<double, 2>> best;
    for (int ring = 1; ring * kStep <= kMostMove + 1e-9 && !best; ++ring) {
        const double r = ring * kStep;
        const int n = std::max(8, int(std::ceil(2 * kPi * r / kStep)));
        for (int k = 0; k < n; ++k) {
            const std::array<double, 2> p{util::rounded(x + r * std::cos(2 * kPi * k / n), 2),
                                          util::rounded(y + r * std::sin(2 * kPi * k / n), 2)};
            const auto d = [&](const std::array<double, 2>& q) { return std::hypot(q[0] - x, q[1] - y); };
            if ((!best || d(p) < d(*best)) && fits(p[0], p[1])) best = p;
        }
    }
    return best;
}

// A start given in the file: kept where it fits, else moved to the nearest place within kMostMove that
// does, else left out; the note says why and where.
std::optional<std::array<double, 2>> Importer::given_start(const Group& g) {
    const XMLElement& e = *g.element;
    const std::string why = misfit(g.start.x, g.start.y);
    if (why.empty()) return std::array<double, 2>{g.start.x, g.start.y};
    const auto moved = nearest_fit(g.start.x, g.start.y);
    if (!moved) {
        note(e, why + ", and no place within " + num(kMostMove) + " m has room: left out");
        return std::nullopt;
    }
    const double d = std::hypot((*moved)[0] - g.start.x, (*moved)[1] - g.start.y);
    note(e, why + ": moved " + num(d) + " m to (" + num((*moved)[0]) + ", " + num((*moved)[1]) +
                "), the nearest place with room");
    return moved;
}

// A start with room to stand but not to turn round: the agent faces along the nearest wall or obstacle
// edge, the way nearer its own heading, and a note says so.
double Importer::face_along(const Group& g, const std::array<double, 2>& start, double heading) {
    const double along = util::rounded(along_nearest_solid(start[0], start[1], heading), 9);
    note(*g.element, "starts " + num(solid_distance(start[0], start[1])) + " m from a wall or an obstacle: room to " +
                         "stand, not to turn round (" + num(room_.wall_clearance) + " m); faces along it, heading " +
                         num(degrees(along)) + " degrees (turned " + num(degrees(wrap_angle(along - heading))) + ")");
    return along;
}

// An agent of the group at `start`: heading as SteerSuite's direction (none: facing its first goal), its
// goals in turn; with none it stands at its start, and a sequence that ends idle stands at its last.
AgentSpec Importer::agent_at(const Group& g, const std::array<double, 2>& start,
                             std::vector<std::array<double, 2>> goals) {
    const bool stands = goals.empty() || g.goals.stands;
    if (goals.empty()) goals.push_back(start);
    double heading = std::atan2(goals[0][1] - start[1], goals[0][0] - start[0]);
    if (g.direction.random)
        heading = radians(util::rounded(rng_.uniform(-180, 180), 1));
    else if (g.direction.x != 0 || g.direction.y != 0)
        heading = std::atan2(g.direction.y, g.direction.x);
    drew_ = drew_ || g.direction.random;
    if (!clear_of_solids(start[0], start[1], room_.wall_clearance)) heading = face_along(g, start, heading);
    AgentSpec a;
    a.start = {start[0], start[1], heading, 0.0};
    a.goals = std::move(goals);
    a.at_goal = stands ? AtGoal::Stay : options_.at_goal;
    return a;
}

// The group's agents: those whose start the file gives first (random = false), then the random ones
// around them, so that a random draw never pushes out an agent placed by hand.
void Importer::place(const Group& g, std::vector<AgentSpec>& out, bool random) {
    if (g.start.random != random || (random && g.kind == "agentEmitter")) return;
    int placed = 0;
    for (; placed < g.count; ++placed) {
        std::optional<std::array<double, 2>> start;
        if (random) {
            start = random_start(g.region ? *g.region : Box{s_.world.x0, s_.world.y0, s_.world.x1, s_.world.y1, ""});
            if (!start) break;
            drew_ = true;
        } else if (!(start = given_start(g))) {
            return;
        }
        std::vector<std::array<double, 2>> goals;
        if (!goals_of(g, goals)) {
            note(*g.element, "its goal (" + num(goals.back()[0]) + ", " + num(goals.back()[1]) +
                                 ") is outside the world: " + (g.count == 1 ? "left out" : "its agents are left out"));
            return;
        }
        out.push_back(agent_at(g, *start, std::move(goals)));
        starts_.add((*start)[0], (*start)[1]);
        goals_.add(out.back().goals.back()[0], out.back().goals.back()[1]);
        kept_starts_.push_back(*start);
        kept_lines_.push_back(g.element->GetLineNum());
    }
    if (placed < g.count)
        note(*g.element, "room for " + std::to_string(placed) + " of its " + std::to_string(g.count) +
                             " agents (starts " + num(room_.wall_clearance) + " m from walls and obstacles, " +
                             num(2 * room_.hold_radius) + " m apart): the rest left out");
}

// What became of each goal that is not a seekStaticTarget, of an agent with no goal left, of an emitter
// and of a region's bounds.
void Importer::group_notes(const Group& g) {
    const XMLElement& e = *g.element;
    if (g.region && !g.region->repaired.empty())
        note(e, "its regionBounds' " + g.region->repaired + ": read with min and max swapped");
    if (g.kind == "agentEmitter")
        note(e,
             g.start.random ? "a random position: SteerSuite's reader places no such emitter: left out" : kEmitterNote);
    for (const Finding& f : g.goals.findings) note(*f.element, f.message);
    if (g.goals.targets.empty() && !g.goals.stands)
        note(e, "no goal mobb's agents pursue is left: " +
                    (g.count == 1 ? std::string("the agent stands at its start")
                                  : "its " + std::to_string(g.count) + " agents stand at their starts") +
                    " to the end of the run (its goal is its start, at_goal \"stay\")");
}

// Speeds and radii (always SteerSuite's own, never mobb's), goals two agents would share, steering
// algorithms named per goal.
void Importer::file_notes(const std::vector<Group>& groups) {
    double lo = INFINITY, hi = -INFINITY, r_lo = INFINITY, r_hi = -INFINITY;
    int behaviours = 0;
    for (const Group& g : groups) {
        lo = std::min(lo, g.speed);
        hi = std::max(hi, g.speed);
        r_lo = std::min(r_lo, g.radius);
        r_hi = std::max(r_hi, g.radius);
        behaviours += g.goals.behaviours;
        for (const Target& t : g.goals.targets) {
            lo = std::min(lo, t.speed);
            hi = std::max(hi, t.speed);
        }
    }
    if (groups.empty()) return;
    const auto range = [](double a, double b) { return a == b ? num(a) : num(a) + " to " + num(b); };
    note("speeds of " + range(lo, hi) + " m/s ignored: mobb's agents walk at their clips' speeds (" +
         num(room_.walk_speed) + " m/s on average)");
    note("radii of " + range(r_lo, r_hi) + " m ignored: mobb's agents are their clips' disks (" +
         num(room_.walk_width / 2) + " m or wider while walking)");
    if (behaviours > 0)
        note(std::to_string(behaviours) +
             " goals name a <Behaviour> (SteerSuite's steering algorithm and its parameters for that goal): "
             "ignored, mobb's agents choose their clips by the crowd's own rules");
    std::size_t shared = 0;  // goals_ holds every kept agent's last goal, its own included
    for (const AgentSpec& a : s_.agents)
        shared += a.at_goal == AtGoal::Stay && goals_.near(a.goals.back()[0], a.goals.back()[1]) > 1;
    if (shared > 0)
        note(std::to_string(shared) + " agents that stay at their goal have one within " + num(2 * room_.hold_radius) +
             " m of another's: an agent at its goal stands there for good, so not all of them can reach theirs");
    if (drew_)
        note("random positions, directions and goals drawn with seed " + std::to_string(options_.seed) +
             " (util::Random), not SteerSuite's draw");
}

// Twice the longest straight walk at the clips' speed plus 20 s, in whole tens, within SteerSuite's own
// timeDurations; or the one asked for.
void Importer::time_limit(const std::vector<Group>& groups) {
    if (options_.time_limit > 0) {
        s_.time_limit = options_.time_limit;
        return;
    }
    double longest = 0, allowed = 0;
    for (const AgentSpec& a : s_.agents) {
        double length = 0, x = a.start.x, y = a.start.y;  // from the start through the goals in turn
        for (const auto& g : a.goals) length += std::hypot(g[0] - x, g[1] - y), x = g[0], y = g[1];
        longest = std::max(longest, length);
    }
    for (const Group& g : groups) allowed = std::max(allowed, g.goals.duration);
    const double estimate = 10 * std::ceil((2 * longest / std::max(room_.walk_speed, 0.1) + 20) / 10);
    s_.time_limit = allowed > 0 ? std::min(estimate, allowed) : estimate;
    note("time limit " + num(s_.time_limit) + " s: twice the longest straight walk (" + num(longest) + " m) at " +
         num(room_.walk_speed) + " m/s plus 20 s" +
         (allowed > 0 ? ", within SteerSuite's timeDuration (" + num(allowed) + " s)" : std::string()));
}

}  // namespace mobb::crowd::steersuite
