// mobb.crowd_poses: the pose of agent K at time t (crowd/agent_pose.h), blended as the viewer's and
// `mobb export-crowd`'s, as numpy arrays.
#include <optional>
#include <stdexcept>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "mobb/crowd/motion/agent_pose.h"

namespace mobb::python {

namespace {

crowd::RigJoints rig_joints(const std::string& joints) {
    if (joints == "all") return crowd::RigJoints::All;
    if (joints == "major") return crowd::RigJoints::Major;
    throw std::invalid_argument("joints: expected \"all\" or \"major\", got \"" + joints + "\"");
}

struct Posed {
    crowd::Record record;
    std::unique_ptr<crowd::CrowdPoser> poser;
};

std::unique_ptr<Posed> open(const std::string& file, const std::optional<std::string>& graph, double blend,
                            const std::string& joints, bool lock_feet = true) {
    if (!(blend >= 0 && blend <= 10)) throw std::invalid_argument("blend: expected seconds in [0, 10]");
    auto out = std::make_unique<Posed>();
    out->record = crowd::load_record(file);
    auto g =
        std::make_shared<crowd::MotionGraph>(crowd::load_graph(graph ? *graph : crowd::record_graph_file(out->record)));
    crowd::PoseBlend b;
    b.window = blend;
    crowd::FootLock lock;
    lock.on = lock_feet;
    try {
        out->poser = std::make_unique<crowd::CrowdPoser>(out->record, std::make_shared<crowd::PoseSources>(g),
                                                         rig_joints(joints), b, lock);
    } catch (const crowd::GraphError& e) {
        throw std::invalid_argument(file + ": " + e.what());
    }
    return out;
}

py::array_t<double> crowd_poses(const std::string& file, const std::optional<std::vector<int>>& agents_arg,
                                const std::optional<std::vector<double>>& times_arg,
                                const std::optional<std::string>& graph, double blend, const std::string& joints,
                                bool lock_feet) {
    const auto posed = open(file, graph, blend, joints, lock_feet);
    const crowd::Record& r = posed->record;
    std::vector<int> agents;
    if (agents_arg) {
        agents = *agents_arg;
        for (std::size_t i = 0; i < agents.size(); ++i)
            if (agents[i] < 0 || std::size_t(agents[i]) >= r.tracks.size())
                throw std::invalid_argument("agents[" + std::to_string(i) + "]: agent " + std::to_string(agents[i]) +
                                            " is not in the record (" + std::to_string(r.tracks.size()) + " agents)");
    } else {
        for (int a = 0; a < int(r.tracks.size()); ++a) agents.push_back(a);
    }
    std::vector<double> times;
    if (times_arg) {
        times = *times_arg;
        const double end = double(r.frames) * r.dt;
        for (std::size_t i = 0; i < times.size(); ++i)
            if (!(times[i] >= 0 && times[i] <= end))
                throw std::invalid_argument("times[" + std::to_string(i) + "]: expected seconds in [0, " +
                                            std::to_string(end) + "], got " + std::to_string(times[i]));
    } else {
        for (std::int64_t k = 0; k < r.frames; ++k) times.push_back(double(k) * r.dt);
    }
    const auto joints_n = py::ssize_t(posed->poser->rig().size());
    py::array_t<double> out({py::ssize_t(agents.size()), py::ssize_t(times.size()), joints_n, py::ssize_t(3)});
    auto o = out.mutable_unchecked<4>();
    {
        py::gil_scoped_release release;
        std::vector<glm::dvec3> pose;
        for (std::size_t a = 0; a < agents.size(); ++a)
            for (std::size_t f = 0; f < times.size(); ++f) {
                if (!posed->poser->pose_at(agents[a], times[f], pose))
                    throw std::runtime_error(file + ": agent " + std::to_string(agents[a]) + " has no pose at " +
                                             std::to_string(times[f]) + " s");
                for (py::ssize_t j = 0; j < joints_n; ++j)
                    for (py::ssize_t c = 0; c < 3; ++c)
                        o(py::ssize_t(a), py::ssize_t(f), j, c) = pose[std::size_t(j)][int(c)];
            }
    }
    return out;
}

}  // namespace

void add_poses(py::module_& m) {
    m.def("crowd_poses", &crowd_poses, py::arg("record"), py::arg("agents") = py::none(), py::arg("times") = py::none(),
          py::kw_only(), py::arg("graph") = py::none(), py::arg("blend") = 0.25, py::arg("joints") = "all",
          py::arg("lock_feet") = true,
          R"doc(Joint positions of a crowd record's agents, blended at clip starts and with planted feet locked, as the
viewer and `mobb export-crowd`.

record  a crowd record file (mobb crowd --record, or mobb.crowd(record=...)).
agents  agent indices (None: all); times: seconds, 0 <= t <= frames * dt (None: every frame k * dt).
graph   the motion graph (None: the one the record names); blend: seconds over which a clip start eases
        out of the previous clip (0: the raw clips); joints: "all" (every joint all sources share) or "major";
        lock_feet: hold planted feet where they came down (False: as the blended clips put them).
Returns a (agents, times, joints, 3) float64 array of ground coordinates (x, y, h) in metres, h above the
floor; joint 0 is the root's ground point, on the record's track. Joint names: crowd_joints.)doc");
    m.def(
        "crowd_joints",
        [](const std::string& file, const std::optional<std::string>& graph, const std::string& joints) {
            const auto posed = open(file, graph, 0.0, joints);
            return py::make_tuple(posed->poser->rig().names, posed->poser->rig().parents);
        },
        py::arg("record"), py::kw_only(), py::arg("graph") = py::none(), py::arg("joints") = "all",
        "The joints crowd_poses returns, as (names, parents); parents[0] is -1.");
}

}  // namespace mobb::python
