// CrowdTuning's fields by name, so that any of them can be set from the command line
// (`mobb crowd --tune NAME=VALUE`) and a tuning is measured without a rebuild.
#include "mobb/crowd/tuning.h"

#include <charconv>
#include <stdexcept>
#include <variant>

#include "mobb/io/load.h"

namespace mobb::crowd {

namespace {

using Member = std::variant<bool CrowdTuning::*, int CrowdTuning::*, double CrowdTuning::*>;

struct Field {
    const char* name;
    Member member;
};

// clang-format off
// One line per field of tuning.h, in its order.
const Field kFields[] = {
    {"moving_speed", &CrowdTuning::moving_speed},
    {"escape_steps", &CrowdTuning::escape_steps},
    {"escape_routes", &CrowdTuning::escape_routes},
    {"wall_margin", &CrowdTuning::wall_margin},
    {"stand_near_walls", &CrowdTuning::stand_near_walls},
    {"leave_in_stride", &CrowdTuning::leave_in_stride},
    {"right_of_way", &CrowdTuning::right_of_way},
    {"right_of_way_after", &CrowdTuning::right_of_way_after},
    {"max_yielding", &CrowdTuning::max_yielding},
    {"give_way", &CrowdTuning::give_way},
    {"give_way_after", &CrowdTuning::give_way_after},
    {"give_way_reach", &CrowdTuning::give_way_reach},
    {"standing_gap", &CrowdTuning::standing_gap},
    {"standing_gap_width", &CrowdTuning::standing_gap_width},
    {"look_ahead", &CrowdTuning::look_ahead},
    {"look_ahead_budget", &CrowdTuning::look_ahead_budget},
    {"look_ahead_dead_end", &CrowdTuning::look_ahead_dead_end},
    {"look_ahead_learns", &CrowdTuning::look_ahead_learns},
    {"follow", &CrowdTuning::follow},
    {"follow_angle", &CrowdTuning::follow_angle},
    {"follow_goal_reach", &CrowdTuning::follow_goal_reach},
    {"goal_walking", &CrowdTuning::goal_walking},
    {"goal_turning", &CrowdTuning::goal_turning},
    {"goal_personal", &CrowdTuning::goal_personal},
    {"goal_crowding", &CrowdTuning::goal_crowding},
    {"goal_patience", &CrowdTuning::goal_patience},
    {"goal_horizon", &CrowdTuning::goal_horizon},
    {"nav_clearance", &CrowdTuning::nav_clearance},
};
// clang-format on

bool parse_bool(const std::string& text) {
    if (text == "true" || text == "on" || text == "1") return true;
    if (text == "false" || text == "off" || text == "0") return false;
    throw std::invalid_argument("is not true or false");
}

int parse_int(const std::string& text) {
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc{} || end != text.data() + text.size()) throw std::invalid_argument("is not an integer");
    return v;
}

}  // namespace

void set_tuning(CrowdTuning& tuning, const std::string& assignment) {
    const std::size_t eq = assignment.find('=');
    const std::string name = assignment.substr(0, eq);
    for (const Field& f : kFields) {
        if (name != f.name) continue;
        if (eq == std::string::npos) throw std::invalid_argument(name + ": no value (NAME=VALUE)");
        const std::string value = assignment.substr(eq + 1);
        if (const auto* d = std::get_if<double CrowdTuning::*>(&f.member)) {
            tuning.*(*d) = io::parse_number(value, name);  // "NAME: 'VALUE' is not a finite number"
            return;
        }
        try {
            if (const auto* b = std::get_if<bool CrowdTuning::*>(&f.member)) tuning.*(*b) = parse_bool(value);
            if (const auto* i = std::get_if<int CrowdTuning::*>(&f.member)) tuning.*(*i) = parse_int(value);
        } catch (const std::invalid_argument& e) {
            std::string what = name;
            what.append(": '").append(value).append("' ").append(e.what());
            throw std::invalid_argument(what);
        }
        return;
    }
    std::string fields;
    for (const Field& f : kFields) {
        if (!fields.empty()) fields += ", ";
        fields += f.name;
    }
    throw std::invalid_argument("'" + name + "' is not a field of CrowdTuning (" + fields + ")");
}

}  // namespace mobb::crowd
