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

Box ground_box(const Source& src, const XMLElement& e) {
    const Box b{field(src, e, "xmin"), field(src, e, "zmin"), field(src, e, "xmax"), field(src, e, "zmax")};
    field(src, e, "ymin");
    field(src, e, "ymax");
    if (b.x0 > b.x1) src.fail(e, "xmin is above xmax");
    if (b.y0 > b.y1) src.fail(e, "zmin is above zmax");
    return b;
}

Ground ground(const Source& src, const XMLElement& e) {
    if (const XMLElement* r = find(e, "random"); r && trimmed(r->GetText()) == "true") return {true};
    const Ground g{false, field(src, e, "x"), field(src, e, "z")};
    if (const XMLElement* y = find(e, "y")) number(src, *y);  // the height: checked, dropped
    return g;
}

Goals goal_sequence(const Source& src, const XMLElement& sequence) {
    Goals g;
    for (const XMLElement* c = sequence.FirstChildElement(); c; c = c->NextSiblingElement()) {
        const std::string kind = local_name(*c);
        if (const XMLElement* d = find(*c, "timeDuration")) g.duration += number(src, *d);
        if (kind != "seekStaticTarget") {
            g.others.insert(kind);
            continue;
        }
        g.targets.push_back({ground(src, need(src, *c, "targetLocation")), field(src, *c, "desiredSpeed")});
        field(src, *c, "timeDuration");
    }
    if (g.targets.empty() && g.others.empty()) src.fail(sequence, "needs at least one goal");
    return g;
}

Group agent_group(const Source& src, const XMLElement& e, bool region) {
    Group g;
    g.element = &e;
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
