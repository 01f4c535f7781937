// What the Python module's files share: the conversions between numpy arrays / Python objects and the
// library's paths and placements, and each file's part of the module.
#pragma once
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "mobb/core/path.h"

namespace mobb::python {

namespace py = pybind11;

/// A clip's path from a Python object: a mobb.Clip, mobb.Tree or mobb.ClipIndex (its path), or an
/// (n, 4) float array of rows (t, x, y, r) in seconds and metres whose sample spacing is `dt` when given,
/// else t[1] - t[0]. Throws std::invalid_argument naming `what` for anything else.
Path path_from(const py::handle& object, const py::object& dt, const std::string& what);

/// (n, 4) float64 array of rows (t, x, y, r), t = i * dt: what `mobb path` prints.
py::array_t<double> path_array(const Path& path);

/// A placement from a sequence (x, y, theta, t0): metres, metres, radians, seconds. Throws
/// std::invalid_argument naming `what` when it is not four finite numbers.
Placement placement_from(const py::handle& object, const std::string& what);

void add_clip(py::module_& m);    // clip.cpp: Clip, load
void add_query(py::module_& m);   // query.cpp: Tree, ClipIndex, collide, collide_batch, clearance
void add_crowd(py::module_& m);   // crowd.cpp: crowd
void add_poses(py::module_& m);   // poses.cpp: crowd_poses, crowd_joints
void add_record(py::module_& m);  // record.cpp: read_record

}  // namespace mobb::python
