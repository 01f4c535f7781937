// Reading a SteerSuite test case's XML (tinyxml2): its elements as plain values, each error one line
// naming the file, the line and the element ("FILE:LINE: element: ..."). What the values become in a
// mobb scenario: steersuite.cpp.
#pragma once
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <tinyxml2.h>

namespace mobb::crowd::steersuite {

using tinyxml2::XMLElement;

inline constexpr int kMostAgents = 100000, kMostObstacles = 10000;

/// The text without white space at either end ("" for none).
std::string trimmed(const char* text);
/// Runs of white space as one space: descriptions are indented over several lines in the files.
std::string one_line(const char* text);
/// SteerSuite's files declare a default namespace; a prefixed one ("sb:agent") reads the same.
std::string local_name(const XMLElement& e);

/// Where errors and notes point: "FILE:LINE: element: ".
struct Source {
    std::string file;

    std::string at(const XMLElement& e) const;
    /// Throws SteerSuiteError at the element.
    [[noreturn]] void fail(const XMLElement& e, const std::string& message) const;
};

/// The first child element of that local name, or null.
const XMLElement* find(const XMLElement& parent, const std::string& name);
/// The same, failing when there is none.
const XMLElement& need(const Source& src, const XMLElement& parent, const std::string& name);
/// The element's text as a finite number, rounded to a micrometre.
double number(const Source& src, const XMLElement& e);
/// number() of the child `name`, which must exist.
double field(const Source& src, const XMLElement& parent, const std::string& name);
/// The child `name` as a whole number from 0 to `most`.
int count(const Source& src, const XMLElement& parent, const std::string& name, int most);

/// A ground rectangle from SteerSuite's bounding box: its x and z (heights are read, then dropped).
struct Box {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
Box ground_box(const Source& src, const XMLElement& e);

/// A point or direction on mobb's ground ((x, z) of SteerSuite's), or <random>true</random>.
struct Ground {
    bool random = false;
    double x = 0, y = 0;
};
Ground ground(const Source& src, const XMLElement& e);

struct Target {
    Ground at;
    double speed = 0;
};

/// A goal sequence: its seekStaticTargets (mobb's goals), the other goal types by name, and how long
/// SteerSuite gives the agent for all of them (seconds).
struct Goals {
    std::vector<Target> targets;
    std::set<std::string> others;
    double duration = 0;
};
Goals goal_sequence(const Source& src, const XMLElement& sequence);

/// An <agent> (one, its start given or random) or an <agentRegion> (count of them, random starts in region).
struct Group {
    const XMLElement* element = nullptr;
    int count = 1;
    std::optional<Box> region;
    Ground start, direction;
    double radius = 0, speed = 0;
    Goals goals;
};
Group agent_group(const Source& src, const XMLElement& e, bool region);

/// tinyxml2's error name as words, and the element it names if any: XML_ERROR_MISMATCHED_ELEMENT and
/// "... XMLElement name=header" -> "mismatched element <header>" (the line is the element's opening tag).
std::string xml_error(const tinyxml2::XMLDocument& doc);

}  // namespace mobb::crowd::steersuite
