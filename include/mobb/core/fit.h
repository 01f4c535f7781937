// Fitting boxes to runs of samples: MOBB (paper 3.1) and UMOBB (paper 4, figure 6).
#pragma once
#include <cstddef>
#include <string>

#include "mobb/core/obb.h"
#include "mobb/core/path.h"

namespace mobb {

/// How an MOBB chooses its major axis.
enum class AxisFit {
    Chord,  ///< first-to-last sample of the node, principal axis if they coincide (paper 3.1)
    Pca,    ///< principal axis of the samples' positions (second-order statistics, as OBB trees)
};

/// The fit of a name on the command line and in scripts: "chord" or "pca". Throws std::invalid_argument
/// "unknown axis fit 'NAME' (chord, pca)".
AxisFit parse_axis_fit(const std::string& name);

/// Safety margin (metres or seconds) added to every fitted half extent, so that rounding in the
/// separating-axis tests can never drop a true contact: boxes are conservative, samples exact.
double fit_margin(const Path& path);

/// MOBB of samples [first, end): 2D box containing every disk (radius r), valid over the local
/// time [first*dt, end*dt]. Requires first < end <= path.size().
Obb2 fit_obb2(const Path& path, std::size_t first, std::size_t end, AxisFit fit = AxisFit::Chord);

/// UMOBB of samples [first, end): 3D space-time box containing every sample's cylinder (base centre
/// (x, y, i*dt), radius r, height dt). Axis a0 runs from the first to the last sample in space-time,
/// a1 is horizontal and orthogonal to a0, a2 = a0 x a1 (paper 4). Returns false, leaving `box`
/// untouched, when a0 is parallel to t (first and last sample at one place, or a single sample):
/// the node is then an extruded 2D box, tested as such (paper Table 1 note).
bool fit_obb3(const Path& path, std::size_t first, std::size_t end, Obb3& box);

/// Principal axis (unit) of the positions of samples [first, end); (1, 0) when they coincide.
glm::dvec2 principal_axis(const Path& path, std::size_t first, std::size_t end);

/// Whether sample i's disk lies inside a 2D box, and its cylinder inside a 3D box (within `tol`).
bool contains(const Obb2& box, const Sample& s, double tol = 0);
bool contains(const Obb3& box, const Sample& s, double t, double dt, double tol = 0);

}  // namespace mobb
