#include "mobb/crowd/motion/crowd_export.h"

#include <cmath>
#include <string>

namespace mobb::crowd {

namespace {

std::array<float, 3> agent_color(int agent) {
    // Hues a golden angle apart, fairly saturated: neighbours in agent order look different.
    const double h = std::fmod(double(agent) * 0.618033988749895, 1.0) * 6.0;
    const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
    const double c = 0.75, m = 0.15;
    double r = 0, g = 0, b = 0;
    switch (int(h)) {
        case 0: r = c, g = c * x; break;
        case 1: r = c * x, g = c; break;
        case 2: g = c, b = c * x; break;
        case 3: g = c * x, b = c; break;
        case 4: r = c * x, b = c; break;
        default: r = c, b = c * x; break;
    }
    return {float(r + m), float(g + m), float(b + m)};
}

std::vector<io::ExportShape> world_shapes(const Record& r) {
    std::vector<io::ExportShape> out;
    const World& w = r.world;
    if (w.walls)
        out.push_back({"walls", Polygon::rectangle(w.x0, w.y0, w.x1, w.y1).vertices, 1.0, {0.45f, 0.45f, 0.5f}});
    for (std::size_t k = 0; k < w.obstacles.size(); ++k)
        out.push_back({"obstacle " + std::to_string(k), w.obstacles[k].vertices, 1.0, {0.55f, 0.4f, 0.3f}});
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (std::size_t g = 0; g < r.tracks[a].goals.size(); ++g) {
            io::ExportShape disk{"goal " + std::to_string(a) + "." + std::to_string(g), {}, 0.0, agent_color(int(a))};
            for (int k = 0; k < 16; ++k) {
                const double ang = 6.283185307179586 * k / 16;
                disk.ground.push_back(
                    {r.tracks[a].goals[g][0] + 0.3 * std::cos(ang), r.tracks[a].goals[g][1] + 0.3 * std::sin(ang)});
            }
            out.push_back(std::move(disk));
        }
    return out;
}

}  // namespace

io::ExportScene crowd_scene(CrowdPoser& poser, const CrowdExportOptions& o) {
    const Record& r = poser.record();
    const int agents = int(r.tracks.size());
    const int a0 = o.agent_begin, a1 = o.agent_end.value_or(agents);
    if (a0 < 0 || a0 >= a1 || a1 > agents)
        throw std::invalid_argument("--agents: expected 0 <= A < B <= " + std::to_string(agents) + ", got " +
                                    std::to_string(a0) + ":" + std::to_string(a1));
    const double last = double(r.frames - 1) * r.dt;
    const double t0 = o.t_begin, t1 = o.t_end.value_or(last);
    if (!(t0 >= 0) || !(t0 <= t1) || !(t1 <= last + 1e-9))
        throw std::invalid_argument("--time: expected 0 <= A <= B <= " + std::to_string(last) + " s, got " +
                                    std::to_string(t0) + ":" + std::to_string(t1));
    const double fps = o.fps > 0 ? o.fps : 1.0 / r.dt;
    if (!(o.fps >= 0) || !(fps <= 1000)) throw std::invalid_argument("--fps: expected 0 < F <= 1000");
    io::ExportScene scene;
    scene.rig.names = poser.rig().names;
    scene.rig.parents = poser.rig().parents;
    scene.dt = 1.0 / fps;
    scene.start = t0;
    scene.frames = int(std::floor((t1 - t0) * fps + 1e-6)) + 1;
    scene.bodies = o.bodies;
    const std::size_t joints = std::size_t(poser.rig().size());
    std::vector<glm::dvec3> pose;
    for (int a = a0; a < a1; ++a) {
        io::ExportSkeleton sk;
        sk.name = "agent " + std::to_string(a);
        sk.color = agent_color(a);
        sk.positions.reserve(joints * std::size_t(scene.frames));
        for (int f = 0; f < scene.frames; ++f) {
            const double t = std::min(t0 + f * scene.dt, last);
            if (!poser.pose_at(a, t, pose) || pose.size() != joints)
                throw std::runtime_error("agent " + std::to_string(a) + " has no pose at " + std::to_string(t) + " s");
            for (const glm::dvec3& p : pose) sk.positions.emplace_back(p);
        }
        scene.skeletons.push_back(std::move(sk));
    }
    if (o.world) scene.shapes = world_shapes(r);
    return scene;
}

}  // namespace mobb::crowd
