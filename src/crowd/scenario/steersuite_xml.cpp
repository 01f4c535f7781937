#include "scenario/steersuite_xml.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "mobb/crowd/scenario/steersuite.h"
#include "mobb/util/json_text.h"

namespace mobb::crowd::steersuite {

std::string trimmed(const char* text) {
    const std::string t = text ? text : "";
    const auto first = t.find_first_not_of(" \t\r\n"), last = t.find_last_not_of(" \t\r\n");
    return first == std::string::npos ? std::string() : t.substr(first, last - first + 1);
}

std::string one_line(const char* text) {
    std::istringstream in(trimmed(text));
    std::string word, out;
    while (in >> word) out += (out.empty() ? "" : " ") + word;
    return out;
}

std::string local_name(const XMLElement& e) {
    const std::string n = e.Name();
    const auto colon = n.find(':');
    return colon == std::string::npos ? n : n.substr(colon + 1);
}

std::string Source::at(const XMLElement& e) const {
    return file + ":" + std::to_string(e.GetLineNum()) + ": " + local_name(e) + ": ";
}

void Source::fail(const XMLElement& e, const std::string& message) const { throw SteerSuiteError(at(e) + message); }

const XMLElement* find(const XMLElement& parent, const std::string& name) {
    for (const XMLElement* c = parent.FirstChildElement(); c; c = c->NextSiblingElement())
        if (local_name(*c) == name) return c;
    return nullptr;
}

const XMLElement& need(const Source& src, const XMLElement& parent, const std::string& name) {
    const XMLElement* c = find(parent, name);
    if (!c) src.fail(parent, "needs <" + name + ">");
    return *c;
}

double number(const Source& src, const XMLElement& e) {
    const std::string t = trimmed(e.GetText());
    char* end = nullptr;
    const double v = t.empty() ? 0 : std::strtod(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(v))
        src.fail(e, "expected a number, got \"" + t + "\"");
    return util::rounded(v, 6);
}

double field(const Source& src, const XMLElement& parent, const std::string& name) {
    return number(src, need(src, parent, name));
}

int count(const Source& src, const XMLElement& parent, const std::string& name, int most) {
    const XMLElement& e = need(src, parent, name);
    const std::string t = trimmed(e.GetText());
    const bool digits =
        !t.empty() && t.size() <= 9 && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits || std::stoi(t) > most)
        src.fail(e, "expected a whole number up to " + std::to_string(most) + ", got \"" + t + "\"");
    return std::stoi(t);
}

namespace {

// A number as the file gives it, for notes (six significant digits: "-100", "0.5").
std::string text_of(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

}  // namespace

Box ground_box(const Source& src, const XMLElement& e) {
    Box b{field(src, e, "xmin"), field(src, e, "zmin"), field(src, e, "xmax"), field(src, e, "zmax"), ""};
    field(src, e, "ymin");
    field(src, e, "ymax");
    const auto order = [&b](double& lo, double& hi, const std::string& axis) {
        if (lo <= hi) return;
        b.repaired += (b.repaired.empty() ? "" : " and ") + axis + "min " + text_of(lo) + " is above " + axis + "max " +
                      text_of(hi);
        std::swap(lo, hi);
    };
    order(b.x0, b.x1, "x");
    order(b.y0, b.y1, "z");
    return b;
}

Ground ground(const Source& src, const XMLElement& e) {
    if (const XMLElement* r = find(e, "random"); r && trimmed(r->GetText()) == "true") return {true};
    const Ground g{false, field(src, e, "x"), field(src, e, "z")};
    if (const XMLElement* y = find(e, "y")) number(src, *y);  // the height: checked, dropped
    return g;
}

std::vector<std::array<double, 2>> given_points(const Source& src, const XMLElement& root) {
    std::vector<std::array<double, 2>> out;
    std::vector<const XMLElement*> todo;
    for (const XMLElement* c = root.FirstChildElement(); c; c = c->NextSiblingElement())
        if (local_name(*c) != "header" && local_name(*c) != "suggestedCameraView") todo.push_back(c);
    while (!todo.empty()) {
        const XMLElement& e = *todo.back();
        todo.pop_back();
        const std::string name = local_name(e);
        if (name == "position" || name == "targetLocation") {
            if (const Ground g = ground(src, e); !g.random) out.push_back({g.x, g.y});
            continue;
        }
        for (const XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) todo.push_back(c);
    }
    return out;
}

namespace {

// A seekStaticTarget's or seekAxisAlignedBoxRegion's point: its targetLocation (random when it or the
// goal's own <random> says so, as SteerSuite reads it); a box without one, the box's centre.
Target target(const Source& src, const XMLElement& goal, bool box) {
    Target t;
    if (const XMLElement* at = find(goal, "targetLocation"); at || !box) {
        t.at = ground(src, at ? *at : need(src, goal, "targetLocation"));
    } else {
        const Box b = ground_box(src, need(src, goal, "goalRegionBounds"));
        t.at = {false, util::rounded((b.x0 + b.x1) / 2), util::rounded((b.y0 + b.y1) / 2)};
    }
    if (const XMLElement* r = find(goal, "random"); r && trimmed(r->GetText()) == "true") t.at.random = true;
    t.speed = field(src, goal, "desiredSpeed");
    return t;
}

std::string box_goal(const Source& src, const XMLElement& goal, const Target& t) {
    const std::string at = t.at.random ? "a random point" : "(" + text_of(t.at.x) + ", " + text_of(t.at.y) + ")";
    std::string box;
    if (const XMLElement* r = find(goal, "goalRegionBounds")) {
        const Box b = ground_box(src, *r);
        box = " (x " + text_of(b.x0) + " to " + text_of(b.x1) + ", z " + text_of(b.y0) + " to " + text_of(b.y1) + ")";
    }
    return "a goal at its targetLocation " + at +
           ", reached within the goal radius; SteerSuite's agents also reach it by touching its box" + box;
}

// What becomes of a goal mobb's agents do not pursue: why it is dropped.
std::string dropped(const XMLElement& goal, const std::string& kind) {
    std::string whom = "a group";
    if (kind == "seekDynamicTarget" || kind == "fleeDynamicTarget") {
        const XMLElement* r = find(goal, "random");
        const XMLElement* name = find(goal, "targetName");
        whom = r && trimmed(r->GetText()) == "true" ? "a random agent"
               : name                               ? "agent \"" + one_line(name->GetText()) + "\""
                                                    : "another agent";
    }
    if (kind == "seekDynamicTarget" || kind == "fleeDynamicTarget" || kind == "groupTarget")
        return "its target is " + whom + ": mobb's goals are fixed points, not other agents: dropped";
    if (kind == "fleeStaticTarget") return "mobb's agents head for points, they do not flee them: dropped";
    if (kind == "flowStaticDirection" || kind == "flowDynamicDirection")
        return "mobb's goals are points, not directions to follow: dropped";
    return "not a goal SteerSuite's reader knows (it refuses such a file): dropped";
}

}  // namespace

Goals goal_sequence(const Source& src, const XMLElement& sequence) {
    Goals g;
    std::vector<std::pair<const XMLElement*, double>> idles;  // each idle and its seconds
    int elements = 0;
    for (const XMLElement* c = sequence.FirstChildElement(); c; c = c->NextSiblingElement(), ++elements) {
        const std::string kind = local_name(*c);
        double seconds = 0;
        if (const XMLElement* d = find(*c, "timeDuration")) g.duration += seconds = number(src, *d);
        g.behaviours += find(*c, "Behaviour") != nullptr;
        if (kind == "seekStaticTarget" || kind == "seekAxisAlignedBoxRegion") {
            const bool box = kind == "seekAxisAlignedBoxRegion";
            g.targets.push_back(target(src, *c, box));
            if (box) g.findings.push_back({c, box_goal(src, *c, g.targets.back())});
            g.stands = false;
        } else if (kind == "idle") {
            idles.emplace_back(c, seconds);
            g.stands = true;
        } else {
            g.findings.push_back({c, dropped(*c, kind)});
        }
    }
    if (elements == 0) src.fail(sequence, "needs at least one goal");
    for (std::size_t k = 0; k < idles.size(); ++k) {
        const bool last = g.stands && k + 1 == idles.size();  // no target after it: the agent stands
        const std::string what = last ? "the agent stands at its last goal (at its start if it has none) to the end "
                                        "of the run, at_goal \"stay\""
                                      : "mobb's agents do not wait between goals: dropped, the agent heads on at once";
        g.findings.push_back({idles[k].first, what + " (SteerSuite's idle " + text_of(idles[k].second) + " s)"});
    }
    return g;
}

Group agent_group(const Source& src, const XMLElement& e) {
    Group g;
    g.element = &e;
    g.kind = local_name(e);
    const bool region = g.kind == "agentRegion";
    if (region) {
        g.count = count(src, e, "numAgents", kMostAgents);
        g.region = ground_box(src, need(src, e, "regionBounds"));
        g.start.random = true;
    }
    const XMLElement& initial = need(src, e, "initialConditions");
    if (!region) g.start = ground(src, need(src, initial, "position"));
    g.direction = ground(src, need(src, initial, "direction"));
    g.radius = field(src, initial, "radius");
    g.speed = field(src, initial, "speed");
    g.goals = goal_sequence(src, need(src, e, "goalSequence"));
    return g;
}

Circle circle_obstacle(const Source& src, const XMLElement& e) {
    return {ground(src, need(src, e, "position")), field(src, e, "radius")};
}

OrientedBox oriented_box(const Source& src, const XMLElement& e, bool wall) {
    OrientedBox b;
    b.centre = ground(src, need(src, e, "position"));
    const Ground size = ground(src, need(src, e, "size"));
    b.centre.random = b.centre.random || size.random;
    b.length_x = std::abs(size.x);
    b.length_z = std::abs(size.y);
    if (const XMLElement* t = find(e, "thetaY")) b.theta_y = number(src, *t);
    if (!wall) return b;
    const XMLElement& door = need(src, e, "doorway");
    if (const XMLElement* r = find(door, "random"); r && trimmed(r->GetText()) == "true")
        b.centre.random = true;  // SteerSuite's reader then places no such wall, as for a random position
    else
        b.door_at = field(src, door, "value");
    if (const XMLElement* r = find(door, "doorRadius")) b.door_radius = std::abs(number(src, *r));
    return b;
}

Outline polygon_obstacle(const Source& src, const XMLElement& e) {
    Outline out;
    for (const XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (local_name(*c) != "vertex") continue;
        const Ground v = ground(src, *c);
        out.random = out.random || v.random;
        out.vertices.push_back({v.x, v.y});
    }
    return out;
}

std::string xml_error(const tinyxml2::XMLDocument& doc) {
    std::string name = doc.ErrorName();
    if (name.rfind("XML_ERROR_", 0) == 0) name = name.substr(10);
    for (char& c : name) c = c == '_' ? ' ' : char(std::tolower(static_cast<unsigned char>(c)));
    const std::string detail = doc.ErrorStr() ? doc.ErrorStr() : "";
    const auto at = detail.find("XMLElement name=");
    if (at != std::string::npos) name += " <" + detail.substr(at + 16, detail.find(' ', at + 16) - (at + 16)) + ">";
    return name;
}

}  // namespace mobb::crowd::steersuite
