// Goal-directed crowd scenarios (`mobb crowd --scenario FILE`): a world with its obstacles, agents with a
// start, a heading, a start time and a goal, and a time limit. Modelled on SteerSuite's public test cases
// (oncoming, crossing, 4-way confusion, hallway and doorway two-way, circle, bottleneck, random with
// obstacles). A scenario passes when every agent reaches its goal in time with no contact at any frame.
//
// JSON (metres, seconds, degrees):
//   {"name": "...", "description": "...", "source": "what it is modelled on",
//    "world": [x0, y0, x1, y1], "walls": true,
//    "obstacles": [ {"rectangle": [x0, y0, x1, y1]} | {"polygon": [[x, y], ...]}, ... ],
//    "time_limit": s, "at_goal": "stay" | "leave",
//    "agents": [ {"start": [x, y], "heading": deg, "start_time": s,
//                 "goal": [x, y] | "goals": [[x, y], ...], "at_goal": "stay" | "leave"}, ... ]}
// "agents" may be empty: a map, its world alone (a SteerSuite test case with no agent); `mobb crowd` needs
// at least one to run it. "walls", "obstacles", "start_time", "description" and "at_goal" may be left
// out; "heading" defaults to facing the (first) goal. "goals" are reached in turn (SteerSuite's
// goalSequence of static targets).
// "at_goal" (the scenario's for every agent, an agent's for itself; "stay" when left out): at its last
// goal an agent stands for good, within the goal radius to the end of the run ("stay"), or leaves the run
// - an exit, a door - its track ending there and its ground free ("leave", SteerSuite's semantics).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "mobb/crowd/options.h"
#include "mobb/crowd/world/world.h"

namespace mobb::crowd {

struct Scenario {
    std::string name, description, source;
    World world;
    std::vector<AgentSpec> agents;
    double time_limit = 60;         ///< seconds
    AtGoal at_goal = AtGoal::Stay;  ///< the agents' unless they say otherwise
};

/// Reads a scenario. Throws std::runtime_error "FILE: KEY: message" (one line) on any problem: a missing
/// file, bad JSON, unknown keys, wrong types, an agent or goal outside the world, both or neither of
/// "goal" and "goals", an "at_goal" other than "stay" or "leave".
Scenario load_scenario(const std::string& file);
Scenario parse_scenario(const nlohmann::json& json, const std::string& where);

/// The crowd options that run it: its world and agents, the goal policy, its time limit.
CrowdOptions scenario_options(const Scenario& scenario);

/// The shipped scenarios: assets/scenarios under the working directory if it exists, else in the
/// source tree this was built from.
std::string default_scenario_folder();
/// The scenario files (*.json) of a folder, sorted by name.
std::vector<std::string> scenario_files(const std::string& folder);

/// The scenario as JSON text in the format above, which load_scenario reads back: coordinates to a
/// micrometre, headings to a millionth of a degree, number arrays on one line. Rectangles (as
/// Polygon::rectangle makes them) are written as "rectangle", other obstacles as "polygon"; one goal as
/// "goal", more as "goals"; an agent without a goal is written without one (load_scenario refuses it).
std::string scenario_json(const Scenario& scenario);

}  // namespace mobb::crowd
