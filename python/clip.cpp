// mobb.load and mobb.Clip: a clip as the loader gives it (io/load.h), its path and joints as arrays.
#include <optional>

#include <pybind11/stl.h>

#include "bindings.h"
#include "mobb/io/load.h"

namespace mobb::python {

namespace {

// Joint positions per frame, (frames, joints, 3), metres in the file's axes (io/animation.h).
py::array_t<double> joints_array(const io::Animation& anim) {
    const auto frames = py::ssize_t(anim.frames()), joints = py::ssize_t(anim.skeleton.size());
    py::array_t<double> out({frames, joints, py::ssize_t(3)});
    auto o = out.mutable_unchecked<3>();
    for (py::ssize_t f = 0; f < frames; ++f)
        for (py::ssize_t j = 0; j < joints; ++j) {
            const glm::dvec3& p = anim.at(int(f), int(j));
            o(f, j, 0) = p.x;
            o(f, j, 1) = p.y;
            o(f, j, 2) = p.z;
        }
    return out;
}

py::dict info_of(const io::Clip& clip) {
    const io::Skeleton& sk = clip.animation.skeleton;
    py::dict d;
    d["file"] = clip.file;
    d["samples"] = clip.path.size();
    d["dt"] = clip.path.dt;
    d["duration"] = clip.path.duration();
    d["source_frames"] = clip.source_frames;
    d["source_dt"] = clip.source_dt;
    d["source_index"] = clip.source_index;
    d["scale"] = clip.scale;
    d["scale_reason"] = clip.scale_reason;
    d["up"] = clip.up == io::UpAxis::Y ? "y" : "z";
    d["joint_names"] = sk.names;
    d["parents"] = sk.parents;
    d["end_site"] = std::vector<bool>(sk.end_site.begin(), sk.end_site.end());
    d["root"] = sk.root;
    d["warnings"] = clip.warnings;
    return d;
}

// The loader options as `mobb` takes them on the command line (--up, --scale, --frames, --fps, --skin,
// --animation, --root); parsed by the library, so the messages are the command line's.
io::LoadOptions load_options(const std::string& up, const py::object& scale, const py::object& frames,
                             const std::optional<double>& fps, int skin, const std::string& animation,
                             const std::string& root) {
    io::LoadOptionText text;
    text.up = up;
    if (!scale.is_none()) text.scale = py::str(scale);
    if (py::isinstance<py::str>(frames)) {
        text.frames = frames.cast<std::string>();
    } else if (!frames.is_none()) {
        const auto ab = frames.cast<std::pair<py::object, py::object>>();
        text.frames =
            std::string(py::str(ab.first)) + ":" + (ab.second.is_none() ? "" : std::string(py::str(ab.second)));
    }
    text.skin = skin;
    text.animation = animation;
    text.root = root;
    io::LoadOptions options = io::parse_load_options(text);
    options.fps = fps;  // load_clip checks it: "FILE: --fps F must be finite and positive"
    return options;
}

io::Clip load(const py::object& file, const std::string& up, const py::object& scale, const py::object& frames,
              const std::optional<double>& fps, int skin, const std::string& animation, const std::string& root) {
    const std::string name = py::str(py::module_::import("os").attr("fspath")(file));
    const io::LoadOptions options = load_options(up, scale, frames, fps, skin, animation, root);
    py::gil_scoped_release release;
    return io::load_clip(name, options);
}

}  // namespace

void add_clip(py::module_& m) {
    py::class_<io::Clip>(m, "Clip", R"doc(A loaded motion-capture clip (mobb.load).

Attributes:
  path    (n, 4) float64 array of rows (t, x, y, r): sample time t = i * dt (seconds), the root's
          ground position (x, y) and the radius r of the vertical cylinder holding every projected
          joint (metres). The same numbers `mobb path FILE` prints.
  dt      seconds between samples.
  joints  (n, joints, 3) float64 array: every joint's position (End Sites included) at every sample,
          metres, in the file's own axes (Y-up unless loaded with up="z").
  info    dict: file, samples, dt, duration (s), source_frames, source_dt (s), source_index (file frame
          of each sample), scale (metres per file unit), scale_reason, up, joint_names, parents
          (-1 for the root), end_site, root, warnings (e.g. root jumps).)doc")
        .def_property_readonly("path", [](const io::Clip& c) { return path_array(c.path); })
        .def_property_readonly("dt", [](const io::Clip& c) { return c.path.dt; })
        .def_property_readonly("joints", [](const io::Clip& c) { return joints_array(c.animation); })
        .def_property_readonly("info", &info_of)
        .def("__len__", [](const io::Clip& c) { return c.path.size(); })
        .def("__repr__", [](const io::Clip& c) {
            return "<mobb.Clip '" + c.file + "': " + std::to_string(c.path.size()) + " samples, dt " +
                   std::to_string(c.path.dt) + " s>";
        });

    m.def(
        "load", &load, py::arg("file"), py::kw_only(), py::arg("up") = "y", py::arg("scale") = py::none(),
        py::arg("frames") = py::none(), py::arg("fps") = py::none(), py::arg("skin") = 0, py::arg("animation") = "",
        py::arg("root") = "",
        R"doc(Loads a clip file as `mobb path` does (the format by its extension: .bvh, .glb, .gltf, .fbx, ...) -> mobb.Clip.

The loader options are the command line's:
  up         "y" or "z": up axis of BVH data (glTF is always Y-up).
  scale      metres per file unit (a number), or None / "auto": inferred from the skeleton's height.
  frames     keep frames A..B-1: "A:B", "A:" or a pair (A, B) (B None: to the end).
  fps        resample to this many samples per second (None: the file's rate).
  skin       glTF: skin index.
  animation  glTF, FBX: animation name ("" : the first).
  root       the joint projected on the ground ("": the skeleton's root).
Raises mobb.LoadError (a file that cannot be read or makes no sense) or ValueError (a bad option) with
the message `mobb` prints after "error: ".)doc");
}

}  // namespace mobb::python
