// The SteerSuite importer's state and steps, shared by the files that implement them - steersuite.cpp
// (the header, the world, the obstacles, the entry point) and steersuite_agents.cpp (starts, goals, notes,
// the time limit). Private to src/crowd.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mobb/crowd/scenario/steersuite.h"
#include "mobb/util/json_text.h"
#include "mobb/util/random.h"
#include "scenario/steersuite_shapes.h"
#include "scenario/steersuite_xml.h"

namespace mobb::crowd::steersuite {

constexpr int kTries = 1000;  // random draws per agent, obstacle or goal before giving up on room

// Metres, seconds and speeds in notes: to a centimetre, no trailing zeros.
inline std::string num(double x) {
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
inline double box_gap(const std::array<double, 4>& a, const std::array<double, 4>& b) {
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
    bool clear_of_solids(double x, double y, double clearance) const;
    double along_nearest_solid(double x, double y, double heading) const;
    double face_along(const Group& g, const std::array<double, 2>& start, double heading);
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

}  // namespace mobb::crowd::steersuite
