// Goal-directed crowd scenarios (`mobb crowd --scenario FILE`): a world with its obstacles, agents with a
// start, a heading, a start time and a goal, and a time limit. Modelled on SteerSuite's public test cases
// (oncoming, crossing, 4-way confusion, hallway and doorway two-way, circle, bottleneck, random with
// obstacles). A scenario passes when every agent reaches its goal in time with no contact at any frame.
//
// JSON (metres, seconds, degrees):
//   {"name": "...", "description": "...", "source": "what it is modelled on",
//    "world": [x0, y0, x1, y1], "walls": true,
//    "obstacles": [ {"rectangle": [x0, y0, x1, y1]} | {"polygon": [[x, y], ...]}, ... ],
//    "time_limit": s,
//    "agents": [ {"start": [x, y], "heading": deg, "start_time": s, "goal": [x, y]}, ... ]}
// "walls", "obstacles", "start_time" and "description" may be left out; "heading" defaults to facing
// the goal.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "mobb/crowd/crowd.h"
#include "mobb/crowd/world.h"

namespace mobb::crowd {

struct Scenario {
    std::string name, description, source;
    World world;
    std::vector<AgentSpec> agents;
    double time_limit = 60;  ///< seconds
};

/// Reads a scenario. Throws std::runtime_error "FILE: KEY: message" (one line) on any problem: a missing
/// file, bad JSON, unknown keys, wrong types, an agent or goal outside the world.
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
/// Polygon::rectangle makes them) are written as "rectangle", other obstacles as "polygon"; an agent
/// without a goal is written without one (load_scenario refuses it).
std::string scenario_json(const Scenario& scenario);

}  // namespace mobb::crowd
