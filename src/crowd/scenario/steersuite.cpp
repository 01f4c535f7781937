// SteerSuite test cases read with tinyxml2 (Debian's libtinyxml2-dev) and mapped onto a Scenario. What is
// mapped, reported and left out: steersuite.h. Every coordinate is rounded to a micrometre as it is read
// (random ones to a centimetre), so the checks here see the numbers the scenario file will hold.
#include "mobb/crowd/scenario/steersuite.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "choice/escape.h"
#include "mobb/core/angle.h"
#include "mobb/util/json_text.h"
#include "mobb/util/random.h"
#include "scenario/steersuite_shapes.h"
#include "scenario/steersuite_xml.h"

namespace mobb::crowd {

AgentRoom AgentRoom::of(const MotionGraph& graph) {
    const EscapeTable escapes = EscapeTable::build(graph);
    AgentRoom room;
    room.wall_clearance = escapes.turn_clearance;
    room.hold_radius = escapes.hold_radius;
    double slimmest = INFINITY, speeds = 0;  // the walking clip whose widest disk is the smallest
    int walks = 0;
    for (int c = 0; c < int(graph.clips.size()); ++c) {
        const GraphClip& clip = graph.clips[std::size_t(c)];
        if (kind_of(clip, c) != ClipKind::Walk) continue;
        double widest = 0;
        for (const Sample& s : clip.path.samples) widest = std::max(widest, s.r);
        slimmest = std::min(slimmest, widest);
        speeds += std::hypot(clip.exit_x, clip.exit_y) / clip.path.duration();
        ++walks;
    }
    if (walks > 0) {
        room.walk_width = 2 * slimmest;
        room.walk_speed = speeds / walks;
    }
    return room;
}

namespace {

using namespace steersuite;  // the test case's elements read as plain values

constexpr int kTries = 1000;  // random draws per agent, obstacle or goal before giving up on room

// Metres, seconds and speeds in notes: to a centimetre, no trailing zeros.
std::string num(double x) {
    std::ostringstream out;
    out << util::rounded(x, 2);
    return out.str();
}

// Points kept a distance apart, in a grid of cells that distance wide (agents' starts, goals).
class Spacing {
public:
    explicit Spacing(double gap) : gap_(gap) {}
    /// How many points lie closer than the gap to (x, y).
    int near(double x, double y) const {
        const auto [i, j] = cell(x, y);
        int n = 0;
        for (std::int64_t di = -1; di <= 1; ++di)
            for (std::int64_t dj = -1; dj <= 1; ++dj) {
                const auto it = cells_.find(key(i + di, j + dj));
                if (it == cells_.end()) continue;
                for (const auto& p : it->second) n += std::hypot(p[0] - x, p[1] - y) < gap_;
            }
        return n;
    }
    bool clear(double x, double y) const { return near(x, y) == 0; }
    void add(double x, double y) {
        const auto [i, j] = cell(x, y);
        cells_[key(i, j)].push_back({x, y});
    }

private:
    std::pair<std::int64_t, std::int64_t> cell(double x, double y) const {
        return {std::int64_t(std::floor(x / gap_)), std::int64_t(std::floor(y / gap_))};
    }
    static std::int64_t key(std::int64_t i, std::int64_t j) { return i * 2000003 + j; }

    double gap_;
    std::unordered_map<std::int64_t, std::vector<std::array<double, 2>>> cells_;
};

// A solid as the notes name it, its bounds, and the obstacleRegion it came from (-1: none).
struct Solid {
    Polygon shape;
    std::array<double, 4> box;
    std::string name;
    int region = -1;
};

// The gap between two ground boxes (0 when they touch or overlap): a lower bound of their shapes' gap.
double box_gap(const std::array<double, 4>& a, const std::array<double, 4>& b) {
    const double dx = std::max({0.0, a[0] - b[2], b[0] - a[2]}), dy = std::max({0.0, a[1] - b[3], b[1] - a[3]});
    return std::hypot(dx, dy);
}

// SteerSuite's own ground: its default simulation grid, 200 m a side about the origin (gridSizeX, gridSizeZ).
constexpr double kSteerSuiteGround = 100;
// Metres: a start given in the file may move this far to where a mobb agent has room, no farther - the
// crowd's goal radius (CrowdOptions::goal_radius), the tolerance it grants an agent at its goal.
constexpr double kMostMove = 1.0;

const char* const kEmitterNote =
    "mobb keeps the first agent it emits, as an agent from the start (SteerSuite emits it at once), not the "
    "ones it emits again, one each time the last finishes its goals: a mobb agent holds its start from the "
    "first frame (start_time only delays its first step), so no two can share the emitter's start";

class Importer {
public:
    Importer(std::string file, const AgentRoom& room, const ImportOptions& options)
        : src_{std::move(file)},
          room_(room),
          options_(options),
          rng_(options.seed),
          starts_(2 * room.hold_radius),
          goals_(2 * room.hold_radius) {}

    ImportedScenario run(const XMLElement& root);

private:
    void header(const XMLElement& root);
    Box world_of(const Box& w, const XMLElement& root, const XMLElement& bounds);
    void walls();
    bool obstacle(const XMLElement& e, const std::string& kind);
    void box_obstacle(const XMLElement& e);
    void obstacle_region(const XMLElement& e);
    void circle(const XMLElement& e);
    void oriented(const XMLElement& e, bool wall);
    void polygon(const XMLElement& e);
    void add_obstacle(Box b, const XMLElement& e, const std::string& name, int region);
    bool add_shape(const Polygon& p, const XMLElement& e);
    void narrow_gaps();
    bool goals_of(const Group& g, std::vector<std::array<double, 2>>& goals);
    std::string misfit(double x, double y) const;
    std::optional<std::array<double, 2>> nearest_fit(double x, double y) const;
    std::optional<std::array<double, 2>> given_start(const Group& g);
    std::optional<std::array<double, 2>> random_start(const Box& region);
    std::array<double, 2> random_goal();
    void place(const Group& g, std::vector<AgentSpec>& out, bool random);
    AgentSpec agent_at(const Group& g, const std::array<double, 2>& start, std::vector<std::array<double, 2>> goals);
    void group_notes(const Group& g);
    void file_notes(const std::vector<Group>& groups);
    void time_limit(const std::vector<Group>& groups);
    double solid_distance(double x, double y) const;
    bool clear_of_solids(double x, double y) const;
    std::string named(const XMLElement& e) const {
        return "the " + local_name(e) + " at line " + std::to_string(e.GetLineNum());
    }
    void note(const XMLElement& e, const std::string& message) { notes_.push_back(src_.at(e) + message); }
    void note(const std::string& message) { notes_.push_back(src_.file + ": " + message); }

    Source src_;
    AgentRoom room_;
    ImportOptions options_;
    util::Random rng_;
    Scenario s_;
    std::vector<Solid> solids_;
    std::vector<Polygon> world_solids_;       // s_.world.solids(), once every obstacle is in
    std::vector<const XMLElement*> regions_;  // the obstacleRegions, in order
    std::vector<std::string> notes_;
    Spacing starts_, goals_;
    std::vector<std::array<double, 2>> kept_starts_;
    std::vector<int> kept_lines_;  // the line of each kept start given in the file
    bool drew_ = false;            // anything random drawn (one note says so)
};

void Importer::header(const XMLElement& root) {
    const XMLElement& h = need(src_, root, "header");
    const XMLElement& version = need(src_, h, "version");
    if (trimmed(version.GetText()) != "1.0")
        note(version, "version \"" + trimmed(version.GetText()) + "\" read as 1.0, the schema's");
    s_.name = one_line(need(src_, h, "name").GetText());
    if (s_.name.empty()) s_.name = std::filesystem::path(src_.file).stem().string();
    if (const XMLElement* d = find(h, "description")) s_.description = one_line(d->GetText());
    const XMLElement& bounds = need(src_, h, "worldBounds");
    const Box w = world_of(ground_box(src_, bounds), root, bounds);
    s_.world = {w.x0, w.y0, w.x1, w.y1, true, {}};
    s_.source = "SteerSuite test case " + std::filesystem::path(src_.file).filename().string() +
                " (mobb scenario import, seed " + std::to_string(options_.seed) + ")";
    if (s_.description.empty()) s_.description = "Imported from " + s_.source + ".";
    s_.at_goal = options_.at_goal;
}

// The header's bounds, min and max swapped where inverted, when they have area and hold every position
// the file gives; else SteerSuite's own ground, where SteerSuite runs every test case (its reader uses the
// header's bounds only to place random agents and obstacles).
Box Importer::world_of(const Box& w, const XMLElement& root, const XMLElement& bounds) {
    const auto points = given_points(src_, root);
    const auto outside = std::count_if(points.begin(), points.end(), [&](const auto& p) {
        return !(w.x0 <= p[0] && p[0] <= w.x1 && w.y0 <= p[1] && p[1] <= w.y1);
    });
    const bool area = w.x0 < w.x1 && w.y0 < w.y1;
    if (area && outside == 0) {
        if (!w.repaired.empty()) note(bounds, w.repaired + ": read with min and max swapped");
        return w;
    }
    std::string why = w.repaired;
    const auto add = [&why](const std::string& s) { why += (why.empty() ? "" : "; ") + s; };
    if (!area) add("the ground (x, z) has no area");
    if (outside > 0)
        add(std::to_string(outside) + " of the " + std::to_string(points.size()) +
            " positions the file gives (starts, goals) lie outside" +
            (w.repaired.empty() ? "" : " the bounds swapped"));
    note(bounds,
         why +
             ": the world is SteerSuite's own ground, x and z from -100 to 100 (its simulation grid; its reader "
             "uses worldBounds only to place random agents and obstacles)");
    return {-kSteerSuiteGround, -kSteerSuiteGround, kSteerSuiteGround, kSteerSuiteGround, ""};
}

// The world's edges are walls (World::solids), after the obstacles so that notes name obstacles first.
void Importer::walls() {
    const World& W = s_.world;
    const auto wall = [&](double x0, double y0, double x1, double y1, std::string name) {
        solids_.push_back({Polygon::rectangle(x0, y0, x1, y1), {x0, y0, x1, y1}, std::move(name)});
    };
    wall(W.x0 - 1, W.y0 - 1, W.x0, W.y1 + 1, "the wall x = " + num(W.x0));
    wall(W.x1, W.y0 - 1, W.x1 + 1, W.y1 + 1, "the wall x = " + num(W.x1));
    wall(W.x0, W.y0 - 1, W.x1, W.y0, "the wall z = " + num(W.y0));
    wall(W.x0, W.y1, W.x1, W.y1 + 1, "the wall z = " + num(W.y1));
}

// A box clipped to the world (walls stand at its edges anyway); a box with no width is a thin wall.
void Importer::add_obstacle(Box b, const XMLElement& e, const std::string& name, int region) {
    const World& w = s_.world;
    b = {std::max(b.x0, w.x0), std::max(b.y0, w.y0), std::min(b.x1, w.x1), std::min(b.y1, w.y1), ""};
    if (b.x0 > b.x1 || b.y0 > b.y1) {
        if (region < 0) note(e, "outside the world: left out");
        return;
    }
    if (b.x0 == b.x1 && b.y0 == b.y1) {
        if (region < 0) note(e, "a point, not an obstacle: left out");
        return;
    }
    const Polygon p = b.x0 == b.x1 || b.y0 == b.y1 ? Polygon{{{b.x0, b.y0}, {b.x1, b.y1}}}
                                                   : Polygon::rectangle(b.x0, b.y0, b.x1, b.y1);
    s_.world.obstacles.push_back(p);
    solids_.push_back({p, {b.x0, b.y0, b.x1, b.y1}, name, region});
}

// Any other shape, clipped to the world; false (with a note) when nothing of it is inside.
bool Importer::add_shape(const Polygon& p, const XMLElement& e) {
    constexpr double kFarthest = 1e6;  // metres from the origin: scenarios hold nothing farther (scenario.cpp)
    for (const auto& v : p.vertices)
        if (!(std::abs(v[0]) <= kFarthest && std::abs(v[1]) <= kFarthest)) {
            note(e, "reaches farther than 1000 km from the origin: left out");
            return false;
        }
    const Polygon in = clipped(p, s_.world);
    if (in.vertices.size() < 2) {
        note(e, p.vertices.size() < 2 ? "a point, not an obstacle: left out" : "outside the world: left out");
        return false;
    }
    s_.world.obstacles.push_back(in);
    solids_.push_back({in, bounds(in), named(e)});
    return true;
}

void Importer::box_obstacle(const XMLElement& e) {
    const Box b = ground_box(src_, e);
    if (!b.repaired.empty()) note(e, b.repaired + ": read with min and max swapped");
    add_obstacle(b, e, "the obstacle at line " + std::to_string(e.GetLineNum()), -1);
}

// Squares of obstacleSize at random inside the region (SteerSuite draws its own; the seed gives these).
void Importer::obstacle_region(const XMLElement& e) {
    const int region = int(regions_.size());
    regions_.push_back(&e);
    const int n = count(src_, e, "numObstacles", kMostObstacles);
    const Box r = ground_box(src_, need(src_, e, "regionBounds"));
    if (!r.repaired.empty()) note(e, "its regionBounds' " + r.repaired + ": read with min and max swapped");
    const double size = field(src_, e, "obstacleSize");
    field(src_, e, "obstacleHeight");
    if (!(size > 0)) src_.fail(need(src_, e, "obstacleSize"), "must be positive");
    if (size > r.x1 - r.x0 || size > r.y1 - r.y0) src_.fail(e, "obstacleSize is larger than regionBounds");
    for (int k = 0; k < n; ++k) {
        const double x = util::rounded(rng_.uniform(r.x0, r.x1 - size), 2);
        const double y = util::rounded(rng_.uniform(r.y0, r.y1 - size), 2);
        add_obstacle({x, y, x + size, y + size, ""}, e, "", region);
    }
    note(e, std::to_string(n) + " obstacles of " + num(size) + " m drawn at random (seed " +
                std::to_string(options_.seed) + "), not SteerSuite's draw");
}

const char* const kRandomObstacle =
    "a random position, size or door: SteerSuite's reader places no such obstacle (it draws only obstacleRegion "
    "squares): left out";

// A regular polygon around the circle: it holds the whole circle, so every contact with the circle is one
// with the polygon (the crowd stays clear of it), at the cost of its corners.
void Importer::circle(const XMLElement& e) {
    const Circle c = circle_obstacle(src_, e);
    if (c.centre.random) return note(e, kRandomObstacle);
    if (!(c.radius > 0)) return note(e, "radius " + num(c.radius) + " m: not an obstacle: left out");
    if (!add_shape(circle_polygon(c.centre.x, c.centre.y, c.radius), e)) return;
    std::ostringstream reach;
    reach << util::rounded(circle_reach(c.radius) * 1000, 1);
    note(e, "radius " + num(c.radius) + " m at (" + num(c.centre.x) + ", " + num(c.centre.y) + "): a regular " +
                std::to_string(circle_sides(c.radius)) + "-gon around the circle, its corners " + reach.str() +
                " mm beyond it (the fewest sides, at least " + std::to_string(kFewestSides) +
                ", within 1 cm): it holds the whole circle, so collisions stay conservative");
}

// An orientedBoxObstacle's rectangle; an orientedWallObstacle's two sections either side of its door,
// where SteerSuite's OrientedWallObstacle builds them (in the wall's own x: from its start to the door,
// and from past the door to 1 - doorRadius m short of its end).
void Importer::oriented(const XMLElement& e, bool wall) {
    const OrientedBox b = oriented_box(src_, e, wall);
    if (b.centre.random) return note(e, kRandomObstacle);
    const double a = radians(b.theta_y), L = b.length_x;
    if (!wall) {
        add_shape(oriented_rectangle(b.centre.x, b.centre.y, L, b.length_z, b.theta_y), e);
        return;
    }
    const std::array<std::array<double, 2>, 2> sections{
        {{-L / 2, b.door_at - b.door_radius}, {b.door_at + b.door_radius, L / 2 - 1 + b.door_radius}}};
    for (const auto& [u0, u1] : sections) {
        if (!(u1 > u0)) continue;
        const double u = (u0 + u1) / 2;  // the section's centre along the wall, turned as SteerSuite turns it
        add_shape(oriented_rectangle(b.centre.x + u * std::cos(a), b.centre.y - u * std::sin(a), u1 - u0, b.length_z,
                                     b.theta_y),
                  e);
    }
    note(e, "a wall of " + num(L) + " m with a door " + num(2 * b.door_radius) + " m wide at " + num(b.door_at) +
                " m from its centre: two sections where SteerSuite builds them (the second ends " +
                num(1 - b.door_radius) + " m short of the wall's end)");
}

void Importer::polygon(const XMLElement& e) {
    const Outline o = polygon_obstacle(src_, e);
    if (o.random) return note(e, kRandomObstacle);
    add_shape(Polygon{o.vertices}, e);
}

// Every obstacle kind SteerSuite's reader knows; false for anything else.
bool Importer::obstacle(const XMLElement& e, const std::string& kind) {
    if (kind == "obstacle")
        box_obstacle(e);
    else if (kind == "obstacleRegion")
        obstacle_region(e);
    else if (kind == "circleObstacle")
        circle(e);
    else if (kind == "orientedBoxObstacle" || kind == "orientedWallObstacle")
        oriented(e, kind == "orientedWallObstacle");
    else if (kind == "polygonObstacle")
        polygon(e);
    else
        return false;
    return true;
}

// Gaps an agent cannot walk through: one line per pair of obstacles given in the file, one per
// obstacleRegion for its random ones.
void Importer::narrow_gaps() {
    std::map<int, int> per_region;
    for (std::size_t a = 0; a < solids_.size(); ++a)
        for (std::size_t b = a + 1; b < solids_.size(); ++b) {
            if (!(box_gap(solids_[a].box, solids_[b].box) < room_.walk_width)) continue;
            const double d = gap(solids_[a].shape, solids_[b].shape);
            if (!(d > 0 && d < room_.walk_width)) continue;
            if (solids_[a].region >= 0 || solids_[b].region >= 0) {
                ++per_region[std::max(solids_[a].region, solids_[b].region)];
                continue;
            }
            note(solids_[a].name + " and " + solids_[b].name + " leave a gap of " + num(d) + " m; mobb's agents need " +
                 num(room_.walk_width) + " m to walk through: it stays shut to them");
        }
    for (const auto& [region, n] : per_region)
        note(*regions_[std::size_t(region)], std::to_string(n) +
                                                 " gaps between its obstacles and others narrower than the " +
                                                 num(room_.walk_width) + " m mobb's agents need to walk through");
}

double Importer::solid_distance(double x, double y) const {
    double d = INFINITY;
    for (const Solid& s : solids_)
        if (box_gap(s.box, {x, y, x, y}) < d) d = std::min(d, gap(s.shape, x, y));
    return d;
}

// The crowd's own test (Simulation::reserve_starts): the held ground's clearance overlaps no solid.
bool Importer::clear_of_solids(double x, double y) const {
    for (const Polygon& p : world_solids_)
        if (disk_overlaps(p, x, y, room_.wall_clearance)) return false;
    return true;
}

std::optional<std::array<double, 2>> Importer::random_start(const Box& region) {
    const World& w = s_.world;
    const Box r{std::max(region.x0, w.x0), std::max(region.y0, w.y0), std::min(region.x1, w.x1),
                std::min(region.y1, w.y1), ""};
    if (r.x0 > r.x1 || r.y0 > r.y1) return std::nullopt;
    for (int t = 0; t < kTries; ++t) {
        const double x = util::rounded(rng_.uniform(r.x0, r.x1), 2), y = util::rounded(rng_.uniform(r.y0, r.y1), 2);
        if (w.inside(x, y) && clear_of_solids(x, y) && starts_.clear(x, y)) return std::array<double, 2>{x, y};
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
        if (!clear_of_solids(x, y)) continue;
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
    if (!clear_of_solids(x, y)) {
        const double d = solid_distance(x, y);
        return (d > 0 ? "starts " + num(d) + " m from a wall or an obstacle"
                      : std::string("starts inside an obstacle")) +
               "; mobb's agents need " + num(room_.wall_clearance) + " m to turn on the spot";
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
        if (box_gap(bounds(p), {x, y, x, y}) < kMostMove + room_.wall_clearance) near.push_back(&p);
    const auto fits = [&](double px, double py) {
        if (!s_.world.inside(px, py) || !starts_.clear(px, py)) return false;
        return std::none_of(near.begin(), near.end(),
                            [&](const Polygon* p) { return disk_overlaps(*p, px, py, room_.wall_clearance); });
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

ImportedScenario Importer::run(const XMLElement& root) {
    header(root);
    std::vector<Group> groups;
    for (const XMLElement* e = root.FirstChildElement(); e; e = e->NextSiblingElement()) {
        const std::string kind = local_name(*e);
        if (kind == "agent" || kind == "agentRegion" || kind == "agentEmitter")
            groups.push_back(agent_group(src_, *e));
        else if (kind != "header" && kind != "suggestedCameraView" && !obstacle(*e, kind))
            note(*e, "not an element SteerSuite's reader knows (it refuses such a file): ignored");
    }
    walls();
    narrow_gaps();
    world_solids_ = s_.world.solids();
    for (const Group& g : groups) group_notes(g);
    std::vector<std::vector<AgentSpec>> placed(groups.size());
    for (bool random : {false, true})
        for (std::size_t k = 0; k < groups.size(); ++k) place(groups[k], placed[k], random);
    for (const auto& agents : placed) s_.agents.insert(s_.agents.end(), agents.begin(), agents.end());
    file_notes(groups);
    time_limit(groups);
    int case_agents = 0;
    for (const Group& g : groups) case_agents += g.count;
    if (case_agents == 0)
        note("the test case has no agent: the scenario is its world alone, a map (mobb crowd needs agents to run it)");
    return {std::move(s_), std::move(notes_), case_agents};
}

// XML allows its declaration only at the very start; SteerSuite's reader (TinyXML, lenient) reads files
// that open with a comment before it. Such a declaration is blanked (newlines kept, so lines stay).
std::string declaration_first(std::string text) {
    std::size_t at = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // a UTF-8 byte order mark
    const std::size_t first = at;
    while ((at = text.find_first_not_of(" \t\r\n", at)) != std::string::npos && text.compare(at, 4, "<!--") == 0) {
        const std::size_t end = text.find("-->", at + 4);
        if (end == std::string::npos) return text;
        at = end + 3;
    }
    if (at == std::string::npos || at == first || text.compare(at, 5, "<?xml") != 0) return text;
    const std::size_t end = text.find("?>", at);
    if (end == std::string::npos) return text;
    for (std::size_t k = at; k < end + 2; ++k)
        if (text[k] != '\n') text[k] = ' ';
    return text;
}

}  // namespace

ImportedScenario import_steersuite(const std::string& file, const AgentRoom& room, const ImportOptions& options) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SteerSuiteError(file + ": cannot open the test case");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string text = declaration_first(buffer.str());
    tinyxml2::XMLDocument doc;
    if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
        throw SteerSuiteError(file + ":" + std::to_string(std::max(1, doc.ErrorLineNum())) +
                              ": XML: " + xml_error(doc));
    const XMLElement* root = doc.RootElement();
    if (!root) throw SteerSuiteError(file + ":1: XML: no element");
    const Source src{file};
    if (local_name(*root) != "SteerBenchTestCase") src.fail(*root, "expected <SteerBenchTestCase>");
    return Importer(file, room, options).run(*root);
}

}  // namespace mobb::crowd
