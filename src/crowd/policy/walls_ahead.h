// Facing along walls (FaceAlongWallsTuning): which ends leave an agent beside a wall facing into it. Nearer
// a wall than room to turn on the spot, an agent that faces into it can neither walk on nor turn round;
// it has to back away first. The goal policy makes such ends cost more, so that agents reaching a wall
// beside a door face along it.
#pragma once
#include <cmath>

#include "mobb/core/path.h"
#include "mobb/crowd/world/world.h"
#include "policy/nav_field.h"

namespace mobb::crowd {

class WallsAhead {
public:
    /// Metres: `stand` room to stand beside a solid, `turn` room to turn on the spot (EscapeTable's
    /// stand_clearance, turn_clearance); grids of `cell` metres.
    WallsAhead(const World& world, double stand, double turn, double cell)
        : stand_(world, stand, cell), turn_(world, turn, cell) {}

    /// Whether an end at `end` lies nearer a solid than room to turn and faces one: the points half of
    /// `ahead` and `ahead` metres along its heading lie nearer a solid than room to stand. To the grids'
    /// cells: each point is judged by the centre of the cell holding it.
    bool facing_wall(const Placement& end, double ahead) const {
        if (!turn_.blocked(end.x, end.y)) return false;
        const double c = std::cos(end.theta), s = std::sin(end.theta);
        return stand_.blocked(end.x + 0.5 * ahead * c, end.y + 0.5 * ahead * s) ||
               stand_.blocked(end.x + ahead * c, end.y + ahead * s);
    }

private:
    NavGrid stand_, turn_;  ///< cells nearer a solid than room to stand, to turn: not free
};

}  // namespace mobb::crowd
