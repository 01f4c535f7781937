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

#include "mobb/core/angle.h"
#include "mobb/util/json_text.h"
#include "mobb/util/random.h"
#include "plan/escape.h"
#include "scenario/steersuite_importer.h"

namespace mobb::crowd {

AgentRoom AgentRoom::of(const MotionGraph& graph) {
    const EscapeTable escapes = EscapeTable::build(graph);
    AgentRoom room;
    room.wall_clearance = escapes.turn_clearance;
    room.stand_clearance = escapes.stand_clearance;
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

namespace steersuite {
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
// The way along the edge of the solid nearest (x, y) - of the two, the one nearer `heading` (radians).
double Importer::along_nearest_solid(double x, double y, double heading) const {
    const Polygon* nearest = nullptr;
    double d = INFINITY;
    for (const Polygon& p : world_solids_)
        if (const double g = gap(p, x, y); g < d) d = g, nearest = &p;
    if (!nearest) return heading;
    const double along = nearest_edge_angle(*nearest, x, y);
    const double turn = wrap_angle(along - heading);
    return wrap_angle(std::abs(turn) <= kPi / 2 ? along : along + kPi);
}

bool Importer::clear_of_solids(double x, double y, double clearance) const {
    for (const Polygon& p : world_solids_)
        if (disk_overlaps(p, x, y, clearance)) return false;
    return true;
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

}  // namespace steersuite

ImportedScenario import_steersuite(const std::string& file, const AgentRoom& room, const ImportOptions& options) {
    using namespace steersuite;  // the test case's elements read as plain values
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
