// SteerSuite test cases as mobb scenarios (`mobb scenario import FILE.xml --out F.json`).
//
// SteerSuite's test cases (repository SteerSuite/Release, testcases/*.xml, read by its TestCaseReader) are
// XML: <SteerBenchTestCase> holds a <header> (version, name, worldBounds), then obstacles - <obstacle>
// boxes, <obstacleRegion>s of random squares, <circleObstacle>s, <orientedBoxObstacle>s,
// <orientedWallObstacle>s (a wall with a door), <polygonObstacle>s - and agents: <agent>s with their
// <initialConditions> and a <goalSequence>, <agentRegion>s of agents at random positions, and
// <agentEmitter>s. SteerSuite is Y-up: its ground (x, z) is mobb's (x, y), and heights (y) are dropped.
// Units are metres and seconds in both; a direction (x, z) becomes the heading atan2(z, x) (radians in
// AgentSpec, degrees in the JSON), none faces the goal. Coordinates are kept to a micrometre; random ones
// (agentRegion starts, <random> positions, directions and goals, obstacleRegion squares) come from
// ImportOptions::seed, to a centimetre and a tenth of a degree.
//
// What SteerSuite's reader takes, this takes: a comment before the XML declaration, and bounds whose
// minimum is above their maximum (swapped). The world is the header's bounds when they hold every position
// the file gives, else SteerSuite's own ground (x and z from -100 to 100, its simulation grid). A circle
// becomes the regular polygon around it with the fewest sides (8 to 256) whose corners lie within 1 cm of
// it, an oriented box its turned rectangle; every shape is clipped to the world.
//
// What a mobb agent cannot do is not refused but reported, one line per finding (ImportedScenario::notes),
// and mapped as closely as mobb allows. A start given in the file within AgentRoom::stand_clearance of a
// wall or an obstacle (no room to stand), or within 2 x AgentRoom::hold_radius of an agent kept before it,
// moves to the nearest place within 1 m (the crowd's goal radius) where it fits, else the agent is left
// out. One with room to stand but not to turn round (within AgentRoom::wall_clearance) is kept, facing
// along the nearest wall or obstacle edge - the way of the two nearest its own - so that it walks along
// a passage rather than into its side. Random starts keep room to turn. Goals:
// seekStaticTargets become the agent's "goals", reached in turn, as does the targetLocation of a
// seekAxisAlignedBoxRegion; a sequence that ends idle stands at its last goal (at_goal stay); goals with
// no counterpart (flee, dynamic targets, flows) are dropped, and an agent left with none stands at its
// start. An agentEmitter gives its first agent only (mobb's agents hold their start from the first frame).
// At its last goal an agent leaves the run, as SteerSuite's do (ImportOptions::at_goal). Reported and
// kept: gaps narrower than AgentRoom::walk_width, speeds and radii (mobb's agents walk at their clips'
// speeds with their clips' disks), steering behaviours named per goal and - for agents that stay at their
// goals - goals two agents share.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/scenario/scenario.h"

namespace mobb::crowd {

/// A test case that cannot be read: "FILE:LINE: element: message" (one line; "FILE: message" when the
/// file cannot be opened). Not XML, a required element missing, a field that is not a number.
class SteerSuiteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The room mobb's agents need, from a motion graph (metres, metres per second). The defaults are those
/// of the committed graph (assets/graphs/cmu_locomotion.json) rounded up to the centimetre (the speed
/// rounded): 0.9786, 0.5807, 0.4825, 0.9545 m, 1.3805 m/s.
struct AgentRoom {
    /// A start this far from every wall and obstacle: room to turn round on the spot
    /// (EscapeTable::turn_clearance). Random starts keep it; a start given nearer faces along the wall.
    double wall_clearance = 0.98;
    /// A start this far from every wall and obstacle: room to stand (EscapeTable::stand_clearance; `mobb
    /// crowd` refuses a goal agent that starts closer, as its held ground keeps as much from walls).
    double stand_clearance = 0.59;
    /// The ground an agent stands on when it stops (EscapeTable::hold_radius): two starts are at least
    /// twice this apart.
    double hold_radius = 0.49;
    /// The narrowest gap a walking clip passes: twice its widest disk, for the walking clip (ClipKind::Walk)
    /// whose widest disk is the smallest. No agent walks through a narrower one.
    double walk_width = 0.96;
    /// Mean speed of the walking clips, start to exit (m/s): the time limit's estimate.
    double walk_speed = 1.38;

    /// The values of `graph`. Throws std::invalid_argument when it has no idle clip.
    static AgentRoom of(const MotionGraph& graph);
};

struct ImportOptions {
    std::uint64_t seed = 1;  ///< random positions, directions and obstacles (agentRegion, obstacleRegion, <random>)
    /// Seconds; 0: estimated, twice the longest straight walk from a start to its goal at
    /// AgentRoom::walk_speed plus 20 s (through its goals in turn), in whole tens, and no more than the agent's timeDurations.
    double time_limit = 0;
    /// What the agents do at their last goal: leave, as SteerSuite disables an agent that reached its
    /// goal (the default), or stay there.
    AtGoal at_goal = AtGoal::Leave;
};

struct ImportedScenario {
    Scenario scenario;
    /// One line each, no newline: what could not be mapped and what was done instead.
    std::vector<std::string> notes;
    /// The agents the test case holds (a region's count, one per agent and emitter): 0 for a map, whose
    /// scenario is its world alone.
    int case_agents = 0;
};

/// Reads a SteerSuite test case. Throws SteerSuiteError on bad input. The scenario may be left with no agent
/// (a map, or every agent left out: the notes say why). The same file, room and options give the same
/// scenario, ready for scenario_json().
ImportedScenario import_steersuite(const std::string& file, const AgentRoom& room, const ImportOptions& options = {});

}  // namespace mobb::crowd
