// SteerSuite's obstacle shapes as mobb's polygons (metres, vertices to a micrometre), and the distances
// the importer reports. What they are mapped from: steersuite_xml.h; where: steersuite.cpp.
#pragma once
#include "mobb/crowd/world/world.h"

namespace mobb::crowd::steersuite {

/// Metres: the most a circle's polygon reaches beyond the circle, at its corners.
inline constexpr double kCircleReach = 0.01;
inline constexpr int kFewestSides = 8, kMostSides = 256;

/// The sides of a circle's polygon: the fewest (kFewestSides to kMostSides) whose corners lie within
/// kCircleReach of a circle of radius r, r (1 / cos(pi / n) - 1) <= kCircleReach: 16 for 0.5 m, 23 for
/// 1 m, 32 for 2 m, 50 for 5 m.
int circle_sides(double r);
/// How far that polygon's corners lie beyond the circle (metres).
double circle_reach(double r);

/// The regular polygon of circle_sides(r) sides around the circle of centre (x, y), a corner at angle 0:
/// its edges lie a micrometre outside the circle, so that the vertices rounded to the micrometre still
/// hold the whole circle (contacts with the polygon are a superset of those with the circle).
Polygon circle_polygon(double x, double y, double r);

/// SteerSuite's oriented box on the ground: `lx` long along its own x, `lz` along its z, centred on
/// (x, y), turned by theta_y degrees as SteerSuite turns it (Util::rotateInXZPlane: its own x axis
/// points to (cos, -sin) in mobb's (x, y)). One length 0: a segment; both: a point (one vertex).
Polygon oriented_rectangle(double x, double y, double lx, double lz, double theta_y);

/// The part of a convex polygon (or segment) inside the world's rectangle, vertices to a micrometre;
/// fewer than two vertices when none of it is inside (or only a point).
Polygon clipped(const Polygon& p, const World& w);

/// The direction (radians) of the polygon's edge nearest (x, y), from one vertex to the next; for a single
/// point, the direction square to the line from (x, y) to it.
double nearest_edge_angle(const Polygon& p, double x, double y);

/// Distance between two polygons (0 when they touch or overlap); from a point to a polygon (0 inside).
double gap(const Polygon& a, const Polygon& b);
double gap(const Polygon& p, double x, double y);

}  // namespace mobb::crowd::steersuite
