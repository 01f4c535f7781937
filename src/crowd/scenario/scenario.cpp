#include "mobb/crowd/scenario/scenario.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "mobb/core/angle.h"
#include "mobb/util/json_text.h"

namespace mobb::crowd {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& message) {
    throw std::runtime_error(where + ": " + message);
}

void only_keys(const json& j, const std::string& where, const std::set<std::string>& keys) {
    if (!j.is_object()) fail(where, "expected an object");
    for (const auto& item : j.items())
        if (!keys.count(item.key())) fail(where + "." + item.key(), "unknown key");
}

double number(const json& v, const std::string& where) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(where, "expected a finite number");
    return v.get<double>();
}

std::vector<double> numbers(const json& v, std::size_t n, const std::string& where) {
    if (!v.is_array() || v.size() != n) fail(where, "expected " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (std::size_t k = 0; k < n; ++k) out.push_back(number(v[k], where + "[" + std::to_string(k) + "]"));
    return out;
}

Polygon obstacle(const json& j, const std::string& where) {
    only_keys(j, where, {"rectangle", "polygon"});
    if (j.contains("rectangle")) {
        const auto r = numbers(j["rectangle"], 4, where + ".rectangle");
        if (!(r[0] < r[2] && r[1] < r[3]))
            fail(where + ".rectangle", "expected [x0, y0, x1, y1] with x0 < x1, y0 < y1");
        return Polygon::rectangle(r[0], r[1], r[2], r[3]);
    }
    if (!j.contains("polygon") || !j["polygon"].is_array() || j["polygon"].size() < 2)
        fail(where, "expected \"rectangle\" or \"polygon\" (two or more [x, y])");
    Polygon p;
    for (std::size_t k = 0; k < j["polygon"].size(); ++k) {
        const auto v = numbers(j["polygon"][k], 2, where + ".polygon[" + std::to_string(k) + "]");
        p.vertices.push_back({v[0], v[1]});
    }
    return p;
}

// A world a crowd can walk: within 1000 km of the origin, at most a kilometre a side (the goal policy's
// navigation grid covers it in 0.25 m cells).
void check_world_size(const std::vector<double>& w, const std::string& where) {
    for (std::size_t k = 0; k < w.size(); ++k)
        if (std::abs(w[k]) > 1e6) fail(where + "[" + std::to_string(k) + "]", "farther than 1000 km from the origin");
    if (w[2] - w[0] > 1000 || w[3] - w[1] > 1000) fail(where, "at most 1000 m a side");
}

// An obstacle stands inside the world (its edges included).
Polygon within_world(Polygon p, const World& w, const std::string& where) {
    for (std::size_t k = 0; k < p.vertices.size(); ++k)
        if (!w.inside(p.vertices[k][0], p.vertices[k][1]))
            fail(where, "vertex " + std::to_string(k) + " lies outside the world");
    return p;
}

// Seconds: positive, and at most a day (a crowd steps every frame of it).
constexpr double kMaxTimeLimit = 86400;
double time_limit(const json& v, const std::string& where) {
    const double t = number(v, where);
    if (!(t > 0)) fail(where, "must be positive");
    if (t > kMaxTimeLimit) fail(where, "at most " + std::to_string(int(kMaxTimeLimit)) + " s (a day)");
    return t;
}

// Every agent starts before the time limit.
void check_start_times(const Scenario& s, const std::string& where) {
    for (std::size_t k = 0; k < s.agents.size(); ++k)
        if (!(s.agents[k].start_time < s.time_limit))
            fail(where + ".agents[" + std::to_string(k) + "].start_time", "must be before the time limit");
}

AtGoal at_goal(const json& v, const std::string& where) {
    const auto out = v.is_string() ? at_goal_of(v.get<std::string>()) : std::nullopt;
    if (!out) fail(where, "expected \"stay\" or \"leave\"");
    return *out;
}

std::array<double, 2> goal(const json& v, const World& w, const std::string& where) {
    const auto g = numbers(v, 2, where);
    if (!w.inside(g[0], g[1])) fail(where, "outside the world");
    return {g[0], g[1]};
}

// "goal": [x, y], or "goals": [[x, y], ...] reached in turn.
std::vector<std::array<double, 2>> goals(const json& j, const World& w, const std::string& where) {
    if (j.contains("goal") == j.contains("goals")) fail(where, "needs \"goal\" or \"goals\" (not both)");
    if (j.contains("goal")) return {goal(j["goal"], w, where + ".goal")};
    const json& v = j["goals"];
    if (!v.is_array() || v.empty()) fail(where + ".goals", "expected a non-empty array of [x, y]");
    std::vector<std::array<double, 2>> out;
    for (std::size_t k = 0; k < v.size(); ++k)
        out.push_back(goal(v[k], w, where + ".goals[" + std::to_string(k) + "]"));
    return out;
}

AgentSpec agent(const json& j, const World& w, AtGoal at_goal_default, const std::string& where) {
    only_keys(j, where, {"start", "heading", "start_time", "goal", "goals", "at_goal"});
    if (!j.contains("start")) fail(where, "needs \"start\"");
    const auto s = numbers(j["start"], 2, where + ".start");
    if (!w.inside(s[0], s[1])) fail(where + ".start", "outside the world");
    AgentSpec a;
    a.goals = goals(j, w, where);
    a.at_goal = j.contains("at_goal") ? at_goal(j["at_goal"], where + ".at_goal") : at_goal_default;
    const auto& g = a.goals[0];
    const double heading = j.contains("heading") ? radians(number(j["heading"], where + ".heading"))
                                                 : std::atan2(g[1] - s[1], g[0] - s[0]);
    a.start = {s[0], s[1], heading, 0.0};
    if (j.contains("start_time")) {
        a.start_time = number(j["start_time"], where + ".start_time");
        if (a.start_time < 0) fail(where + ".start_time", "must not be negative");
    }
    return a;
}

}  // namespace

Scenario parse_scenario(const json& j, const std::string& where) {
    only_keys(j, where,
              {"name", "description", "source", "world", "walls", "obstacles", "time_limit", "at_goal", "agents"});
    Scenario s;
    const auto text = [&](const char* key) {
        if (!j.contains(key)) return std::string();
        if (!j[key].is_string()) fail(where + "." + key, "expected a string");
        return j[key].get<std::string>();
    };
    s.name = text("name");
    s.description = text("description");
    s.source = text("source");
    if (!j.contains("world")) fail(where, "needs \"world\": [x0, y0, x1, y1]");
    const auto w = numbers(j["world"], 4, where + ".world");
    if (!(w[0] < w[2] && w[1] < w[3])) fail(where + ".world", "expected [x0, y0, x1, y1] with x0 < x1, y0 < y1");
    check_world_size(w, where + ".world");
    s.world = {w[0], w[1], w[2], w[3], true, {}};
    if (j.contains("walls")) {
        if (!j["walls"].is_boolean()) fail(where + ".walls", "expected true or false");
        s.world.walls = j["walls"].get<bool>();
    }
    if (j.contains("obstacles")) {
        if (!j["obstacles"].is_array()) fail(where + ".obstacles", "expected an array");
        for (std::size_t k = 0; k < j["obstacles"].size(); ++k) {
            const std::string at = where + ".obstacles[" + std::to_string(k) + "]";
            s.world.obstacles.push_back(within_world(obstacle(j["obstacles"][k], at), s.world, at));
        }
    }
    if (!j.contains("time_limit")) fail(where, "needs \"time_limit\" (seconds)");
    s.time_limit = time_limit(j["time_limit"], where + ".time_limit");
    if (!j.contains("agents") || !j["agents"].is_array())
        fail(where, "needs \"agents\": an array (empty: a map, its world alone)");
    if (j.contains("at_goal")) s.at_goal = at_goal(j["at_goal"], where + ".at_goal");
    for (std::size_t k = 0; k < j["agents"].size(); ++k)
        s.agents.push_back(agent(j["agents"][k], s.world, s.at_goal, where + ".agents[" + std::to_string(k) + "]"));
    check_start_times(s, where);
    return s;
}

Scenario load_scenario(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file + ": cannot open scenario file");
    const json j = json::parse(in, nullptr, false);
    if (j.is_discarded()) throw std::runtime_error(file + ": not valid JSON");
    return parse_scenario(j, file);
}

CrowdOptions scenario_options(const Scenario& scenario) {
    CrowdOptions o;
    o.world = scenario.world;
    o.placed = scenario.agents;
    o.agents = int(scenario.agents.size());
    o.seconds = scenario.time_limit;
    o.select = Selection::Goal;
    return o;
}

std::string default_scenario_folder() {
    std::string local = "assets/scenarios";
    if (std::filesystem::is_directory(local)) return local;
    return std::string(MOBB_SOURCE_DIR) + "/" + local;
}

std::vector<std::string> scenario_files(const std::string& folder) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec))
        if (e.path().extension() == ".json") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

namespace {

// A rectangle as Polygon::rectangle lays it out, so that it reads back as the same four vertices.
bool is_rectangle(const Polygon& p) {
    const auto& v = p.vertices;
    if (v.size() != 4) return false;
    const bool laid_out = v[1][1] == v[0][1] && v[2][0] == v[1][0] && v[3][0] == v[0][0] && v[3][1] == v[2][1];
    return laid_out && v[0][0] < v[1][0] && v[0][1] < v[2][1];
}

nlohmann::ordered_json obstacle_json(const Polygon& p) {
    const auto m = [](double x) { return util::rounded(x, 6); };
    nlohmann::ordered_json o;
    if (is_rectangle(p)) {
        o["rectangle"] = {m(p.vertices[0][0]), m(p.vertices[0][1]), m(p.vertices[2][0]), m(p.vertices[2][1])};
        return o;
    }
    o["polygon"] = nlohmann::ordered_json::array();
    for (const auto& v : p.vertices) o["polygon"].push_back({m(v[0]), m(v[1])});
    return o;
}

nlohmann::ordered_json agent_json(const AgentSpec& a, AtGoal at_goal_default) {
    const auto m = [](double x) { return util::rounded(x, 6); };
    nlohmann::ordered_json o;
    o["start"] = {m(a.start.x), m(a.start.y)};
    o["heading"] = util::rounded(degrees(a.start.theta), 6);
    if (a.start_time > 0) o["start_time"] = m(a.start_time);
    if (a.goals.size() == 1) o["goal"] = {m(a.goals[0][0]), m(a.goals[0][1])};
    if (a.goals.size() > 1) {
        o["goals"] = nlohmann::ordered_json::array();
        for (const auto& g : a.goals) o["goals"].push_back({m(g[0]), m(g[1])});
    }
    if (a.at_goal != at_goal_default) o["at_goal"] = to_string(a.at_goal);
    return o;
}

}  // namespace

std::string scenario_json(const Scenario& s) {
    nlohmann::ordered_json j;
    j["name"] = s.name;
    if (!s.description.empty()) j["description"] = s.description;
    if (!s.source.empty()) j["source"] = s.source;
    j["world"] = {s.world.x0, s.world.y0, s.world.x1, s.world.y1};
    j["walls"] = s.world.walls;
    j["obstacles"] = nlohmann::ordered_json::array();
    for (const Polygon& p : s.world.obstacles) j["obstacles"].push_back(obstacle_json(p));
    j["time_limit"] = s.time_limit;
    if (s.at_goal != AtGoal::Stay) j["at_goal"] = to_string(s.at_goal);
    j["agents"] = nlohmann::ordered_json::array();
    for (const AgentSpec& a : s.agents) j["agents"].push_back(agent_json(a, s.at_goal));
    return util::readable_json(j);
}

}  // namespace mobb::crowd
