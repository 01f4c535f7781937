// CrowdTuning's fields by name, so that any of them can be set from the command line
// (`mobb crowd --tune NAME=VALUE`) and a tuning is measured without a rebuild: each by its name as the
// fields nest (give_way.reach), and by the flat name it had before (give_way_reach), kept for one release.
#include "mobb/crowd/tuning.h"

#include <charconv>
#include <stdexcept>
#include <variant>
#include <vector>

#include "mobb/io/load.h"

namespace mobb::crowd {

namespace {

using Target = std::variant<bool*, int*, double*>;

struct Field {
    const char* name;  ///< as the fields nest: "give_way.reach"
    const char* flat;  ///< the name of the release before ("give_way_reach"); null when the same
    Target target;
};

// One line per field of tuning.h, in its order.
std::vector<Field> fields_of(CrowdTuning& t) {
    // clang-format off
    return {
        {"moving_speed", nullptr, &t.moving_speed},
        {"escape.steps", "escape_steps", &t.escape.steps},
        {"escape.routes", "escape_routes", &t.escape.routes},
        {"escape.wall_margin", "wall_margin", &t.escape.wall_margin},
        {"stand_near_walls.on", "stand_near_walls", &t.stand_near_walls.on},
        {"leave_in_stride.on", "leave_in_stride", &t.leave_in_stride.on},
        {"right_of_way.on", "right_of_way", &t.right_of_way.on},
        {"right_of_way.after", "right_of_way_after", &t.right_of_way.after},
        {"right_of_way.max_rerouted", "max_yielding", &t.right_of_way.max_rerouted},
        {"give_way.on", "give_way", &t.give_way.on},
        {"give_way.after", "give_way_after", &t.give_way.after},
        {"give_way.reach", "give_way_reach", &t.give_way.reach},
        {"let_through.on", nullptr, &t.let_through.on},
        {"let_through.narrow", nullptr, &t.let_through.narrow},
        {"let_through.reach", nullptr, &t.let_through.reach},
        {"let_through.lane_length", nullptr, &t.let_through.lane_length},
        {"let_through.lane_width", nullptr, &t.let_through.lane_width},
        {"let_through.cost", nullptr, &t.let_through.cost},
        {"let_through.oncoming", nullptr, &t.let_through.oncoming},
        {"keep_right.on", nullptr, &t.keep_right.on},
        {"keep_right.corridor", nullptr, &t.keep_right.corridor},
        {"keep_right.ahead", nullptr, &t.keep_right.ahead},
        {"keep_right.offset", nullptr, &t.keep_right.offset},
        {"keep_right.cost", nullptr, &t.keep_right.cost},
        {"keep_right.stream", nullptr, &t.keep_right.stream},
        {"keep_right.open_cost", nullptr, &t.keep_right.open_cost},
        {"face_along_walls.on", nullptr, &t.face_along_walls.on},
        {"face_along_walls.ahead", nullptr, &t.face_along_walls.ahead},
        {"face_along_walls.cost", nullptr, &t.face_along_walls.cost},
        {"standing_gap.on", "standing_gap", &t.standing_gap.on},
        {"standing_gap.width", "standing_gap_width", &t.standing_gap.width},
        {"look_ahead.on", "look_ahead", &t.look_ahead.on},
        {"look_ahead.budget", "look_ahead_budget", &t.look_ahead.budget},
        {"look_ahead.dead_end", "look_ahead_dead_end", &t.look_ahead.dead_end},
        {"look_ahead.weight", nullptr, &t.look_ahead.weight},
        {"look_ahead.learns", "look_ahead_learns", &t.look_ahead.learns},
        {"follow.on", "follow", &t.follow.on},
        {"follow.angle", "follow_angle", &t.follow.angle},
        {"follow.goal_reach", "follow_goal_reach", &t.follow.goal_reach},
        {"goal.walking", "goal_walking", &t.goal.walking},
        {"goal.turning", "goal_turning", &t.goal.turning},
        {"goal.personal", "goal_personal", &t.goal.personal},
        {"goal.crowding", "goal_crowding", &t.goal.crowding},
        {"goal.patience", "goal_patience", &t.goal.patience},
        {"goal.horizon", "goal_horizon", &t.goal.horizon},
        {"goal.nav_clearance", "nav_clearance", &t.goal.nav_clearance},
        {"goal.neighbourhood", nullptr, &t.goal.neighbourhood},
        {"goal.neighbours_ahead", nullptr, &t.goal.neighbours_ahead},
        {"wander.open_ahead", nullptr, &t.wander.open_ahead},
        {"wander.band", nullptr, &t.wander.band},
    };
    // clang-format on
}

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

// Sets the field `f` names from `value`; `name` as the assignment wrote it, for the error.
void set_field(const Field& f, const std::string& name, const std::string& value) {
    if (double* const* d = std::get_if<double*>(&f.target)) {
        **d = io::parse_number(value, name);  // "NAME: 'VALUE' is not a finite number"
        return;
    }
    try {
        if (bool* const* b = std::get_if<bool*>(&f.target)) **b = parse_bool(value);
        if (int* const* i = std::get_if<int*>(&f.target)) **i = parse_int(value);
    } catch (const std::invalid_argument& e) {
        std::string what = name;
        what.append(": '").append(value).append("' ").append(e.what());
        throw std::invalid_argument(what);
    }
}

}  // namespace

void set_tuning(CrowdTuning& tuning, const std::string& assignment) {
    const std::size_t eq = assignment.find('=');
    const std::string name = assignment.substr(0, eq);
    const std::vector<Field> fields = fields_of(tuning);
    for (const Field& f : fields) {
        if (name != f.name && (f.flat == nullptr || name != f.flat)) continue;
        if (eq == std::string::npos) throw std::invalid_argument(name + ": no value (NAME=VALUE)");
        return set_field(f, name, assignment.substr(eq + 1));
    }
    std::string names;
    for (const Field& f : fields) {
        if (!names.empty()) names += ", ";
        names += f.name;
    }
    throw std::invalid_argument("'" + name + "' is not a field of CrowdTuning (" + names + ")");
}

}  // namespace mobb::crowd
