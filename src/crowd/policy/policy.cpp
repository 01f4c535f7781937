// The policies by name (policy.h); each lives in its own file.
#include "mobb/crowd/policy/policy.h"

#include <stdexcept>

namespace mobb::crowd {

std::unique_ptr<Policy> random_policy();
std::unique_ptr<Policy> wander_policy(const PolicyContext& context);
std::unique_ptr<Policy> goal_policy(const PolicyContext& context);

const char* to_string(Selection s) {
    switch (s) {
        case Selection::Wander: return "wander";
        case Selection::Random: return "random";
        case Selection::Goal: return "goal";
    }
    return "?";
}

Selection parse_selection(const std::string& name) {
    for (Selection s : {Selection::Wander, Selection::Random, Selection::Goal})
        if (name == to_string(s)) return s;
    if (name == "avoid") return Selection::Wander;  // the old name, for one release
    throw std::invalid_argument("unknown selection '" + name + "' (wander, random, goal)");
}

std::unique_ptr<Policy> make_policy(Selection kind, const PolicyContext& context) {
    switch (kind) {
        case Selection::Random: return random_policy();
        case Selection::Goal: return goal_policy(context);
        default: return wander_policy(context);
    }
}

}  // namespace mobb::crowd
