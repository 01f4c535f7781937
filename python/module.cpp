// The Python module `mobb`: clips, trees, queries and crowds of the C++ library (pybind11).
// Errors become Python exceptions carrying the message `mobb` prints after "error: ".
#include "bindings.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/io/load.h"

PYBIND11_MODULE(mobb, m) {
    namespace py = pybind11;
    m.doc() = R"doc(Exact space-time collision detection between motion-capture characters (MOBB / UMOBB trees).

Units: metres, seconds, radians (placements (x, y, theta, t0) take theta in radians, counter-clockwise
seen from above; the command line takes degrees). Arrays are float64 numpy arrays.
Errors: mobb.LoadError (a clip file that cannot be read or makes no sense), mobb.GraphError (a motion
graph), ValueError (bad options or input), TypeError (wrong kinds of object).)doc";
    py::register_exception<mobb::io::LoadError>(m, "LoadError", PyExc_ValueError);
    py::register_exception<mobb::crowd::GraphError>(m, "GraphError", PyExc_ValueError);
    mobb::python::add_clip(m);
    mobb::python::add_query(m);
    mobb::python::add_crowd(m);
    mobb::python::add_poses(m);
    mobb::python::add_record(m);
}
