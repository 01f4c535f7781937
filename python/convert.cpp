// Paths and placements between numpy / Python objects and the library.
#include <cmath>
#include <stdexcept>

#include "bindings.h"
#include "mobb/core/clip_index.h"
#include "mobb/core/tree.h"
#include "mobb/io/load.h"

namespace mobb::python {

namespace {

Path path_of_rows(const py::handle& object, const py::object& dt, const std::string& what) {
    const auto rows = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!rows || rows.ndim() != 2 || rows.shape(1) != 4)
        throw std::invalid_argument(what +
                                    ": expected a mobb.Clip, Tree, ClipIndex or an (n, 4) array of (t, x, y, r)");
    const auto r = rows.unchecked<2>();
    Path path;
    if (!dt.is_none())
        path.dt = dt.cast<double>();
    else if (rows.shape(0) >= 2)
        path.dt = r(1, 0) - r(0, 0);
    else
        throw std::invalid_argument(what + ": dt is needed for a path of fewer than two samples");
    path.samples.resize(std::size_t(rows.shape(0)));
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) path.samples[std::size_t(i)] = {r(i, 1), r(i, 2), r(i, 3)};
    try {
        validate(path);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(what + ": " + e.what());
    }
    return path;
}

}  // namespace

Path path_from(const py::handle& object, const py::object& dt, const std::string& what) {
    if (py::isinstance<io::Clip>(object)) return object.cast<const io::Clip&>().path;
    if (py::isinstance<Tree>(object)) return object.cast<const Tree&>().path();
    if (py::isinstance<ClipIndex>(object)) return object.cast<const ClipIndex&>().path();
    return path_of_rows(object, dt, what);
}

py::array_t<double> path_array(const Path& path) {
    py::array_t<double> out({py::ssize_t(path.size()), py::ssize_t(4)});
    auto o = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Sample& s = path.samples[i];
        const auto k = py::ssize_t(i);
        o(k, 0) = double(i) * path.dt;  // as `mobb path` prints it
        o(k, 1) = s.x;
        o(k, 2) = s.y;
        o(k, 3) = s.r;
    }
    return out;
}

Placement placement_from(const py::handle& object, const std::string& what) {
    const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!v || v.ndim() != 1 || v.shape(0) != 4)
        throw std::invalid_argument(what + ": expected (x, y, theta, t0) (metres, metres, radians, seconds)");
    const double* x = v.data();
    for (int k = 0; k < 4; ++k)
        if (!std::isfinite(x[k])) throw std::invalid_argument(what + ": not finite");
    return {x[0], x[1], x[2], x[3]};
}

}  // namespace mobb::python
