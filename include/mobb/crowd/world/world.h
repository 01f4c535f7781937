// The crowd's world: a rectangle of ground, walled or open, and static obstacles (walls, pillars) as
// polygons. A sample collides with an obstacle exactly as with another agent's sample: when its disk
// overlaps the polygon (the README's model with the polygon in place of the second disk).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "mobb/core/path.h"

namespace mobb::crowd {

/// A simple polygon (no self-intersections), vertices in order (either orientation), metres. Two
/// vertices make a segment (a thin wall).
struct Polygon {
    std::vector<std::array<double, 2>> vertices;

    /// An axis-aligned rectangle [x0, x1] x [y0, y1].
    static Polygon rectangle(double x0, double y0, double x1, double y1);
};

/// Does the disk of centre (x, y) and radius r overlap the polygon: is the centre inside it, or its
/// distance to the boundary below r (strictly; touching is not a collision)? Exact up to the rounding of
/// one squared distance per edge.
bool disk_overlaps(const Polygon& polygon, double x, double y, double r);

/// Axis-aligned bounds of a polygon: {x0, y0, x1, y1}.
std::array<double, 4> bounds(const Polygon& polygon);

/// Whether any sample of `path` placed at `place` overlaps the polygon (time plays no part: obstacles
/// stand for ever). Samples [first, path.size()) only.
bool path_hits(const Path& path, const Placement& place, const Polygon& polygon, std::size_t first = 0);
/// The same with the placement's rotation given (m == Rigid2::of(place)).
bool path_hits(const Path& path, const Rigid2& m, const Polygon& polygon, std::size_t first = 0);

struct World {
    double x0 = 0, y0 = 0, x1 = 30, y1 = 40;  ///< the ground rectangle, metres
    bool walls = true;                        ///< its edges are walls no disk may cross
    std::vector<Polygon> obstacles;           ///< inside the rectangle

    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
    bool inside(double x, double y) const { return x0 <= x && x <= x1 && y0 <= y && y <= y1; }
    /// The obstacles and, when walled, four slabs 1 m thick just outside the rectangle: every polygon
    /// a disk must stay clear of.
    std::vector<Polygon> solids() const;
};

}  // namespace mobb::crowd
