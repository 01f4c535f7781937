// Reading a SteerSuite test case's XML (tinyxml2): its elements as plain values, each error one line
// naming the file, the line and the element ("FILE:LINE: element: ..."). What the values become in a
// mobb scenario: steersuite.cpp.
#pragma once
#include <array>
#include <optional>
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

/// A note on an element: what was mapped, how, or what was dropped.
struct Finding {
    const XMLElement* element = nullptr;
    std::string message;
};

/// A ground rectangle from SteerSuite's bounding box: its x and z (heights are read, then dropped). A
/// minimum above its maximum is swapped, and `repaired` says so ("xmin 5 is above xmax 3"; "" if none).
struct Box {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    std::string repaired;
};
Box ground_box(const Source& src, const XMLElement& e);

/// A point or direction on mobb's ground ((x, z) of SteerSuite's), or <random>true</random>.
struct Ground {
    bool random = false;
    double x = 0, y = 0;
};
Ground ground(const Source& src, const XMLElement& e);

/// The (x, z) of every <position> and <targetLocation> given in the file (not random), the camera's
/// left out: what the world must hold.
std::vector<std::array<double, 2>> given_points(const Source& src, const XMLElement& root);

struct Target {
    Ground at;
    double speed = 0;
};

/// A goal sequence as mobb's goals: its seekStaticTargets, and the targetLocation of each
/// seekAxisAlignedBoxRegion, reached in turn; `stands` when it ends idle (the agent stands at its last
/// goal, or its start, for good); how long SteerSuite gives the agent for all of them (seconds). Every goal
/// that is not a seekStaticTarget gets a finding that says what became of it.
struct Goals {
    std::vector<Target> targets;
    bool stands = false;
    double duration = 0;
    int behaviours = 0;  ///< goals with a <Behaviour> (SteerSuite's steering algorithm for that goal)
    std::vector<Finding> findings;
};
Goals goal_sequence(const Source& src, const XMLElement& sequence);

/// An <agent> (one, its start given or random), an <agentRegion> (count of them, random starts in the
/// region) or an <agentEmitter> (one: mobb keeps the first agent it emits).
struct Group {
    const XMLElement* element = nullptr;
    std::string kind;
    int count = 1;
    std::optional<Box> region;
    Ground start, direction;
    double radius = 0, speed = 0;
    Goals goals;
};
Group agent_group(const Source& src, const XMLElement& e);

/// A <circleObstacle>: centre and radius (metres).
struct Circle {
    Ground centre;
    double radius = 0;
};
Circle circle_obstacle(const Source& src, const XMLElement& e);

/// An <orientedBoxObstacle> or <orientedWallObstacle>: centre, its lengths along its own x and z
/// (SteerSuite's size.x and size.z), turned thetaY degrees about the vertical; a wall's door is door_at
/// metres from its centre along its x, door_radius either side. centre.random when its position, size or
/// door is random.
struct OrientedBox {
    Ground centre;
    double length_x = 0, length_z = 0, theta_y = 0;
    double door_at = 0, door_radius = 0;
};
OrientedBox oriented_box(const Source& src, const XMLElement& e, bool wall);

/// A <polygonObstacle>'s <vertex>es on the ground, in order; random when any vertex is.
struct Outline {
    std::vector<std::array<double, 2>> vertices;
    bool random = false;
};
Outline polygon_obstacle(const Source& src, const XMLElement& e);

/// tinyxml2's error name as words, and the element it names if any: XML_ERROR_MISMATCHED_ELEMENT and
/// "... XMLElement name=header" -> "mismatched element <header>" (the line is the element's opening tag).
std::string xml_error(const tinyxml2::XMLDocument& doc);

}  // namespace mobb::crowd::steersuite
