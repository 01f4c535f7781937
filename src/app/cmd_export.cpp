// mobb export-crowd: a crowd record as animated skeletons for other tools (glTF / GLB, BVH).
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>

#include "cli.h"
#include "mobb/crowd/motion/crowd_export.h"
#include "mobb/crowd/motion/motion_metrics.h"

namespace mobb::app {

namespace {

/// "A:B" -> a, b; an empty side leaves its value as it was. Throws InputError naming the option.
void parse_range(const std::string& text, const std::string& option, std::optional<double>& a,
                 std::optional<double>& b) {
    const auto colon = text.find(':');
    if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos)
        throw InputError(option + ": expected A:B, got '" + text + "'");
    const std::string lo = text.substr(0, colon), hi = text.substr(colon + 1);
    try {
        if (!lo.empty()) a = io::parse_number(lo, option);
        if (!hi.empty()) b = io::parse_number(hi, option);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
}

struct ExportArgs {
    std::string record, out, format, graph, agents, time, joints = "all";
    double fps = 0, blend = 0.25;
    bool body = false, no_world = false, jumps = false, free_feet = false;
};

void run_export(const ExportArgs& a, std::ostream& out) {
    crowd::CrowdExportOptions o;
    if (!a.agents.empty()) {
        std::optional<double> lo, hi;
        parse_range(a.agents, "--agents", lo, hi);
        for (const auto& v : {lo, hi})
            if (v && (*v != std::floor(*v) || std::abs(*v) > 1e9))
                throw InputError("--agents: expected whole numbers A:B, got '" + a.agents + "'");
        if (lo) o.agent_begin = int(*lo);
        if (hi) o.agent_end = int(*hi);
    }
    if (!a.time.empty()) {
        std::optional<double> lo, hi;
        parse_range(a.time, "--time", lo, hi);
        if (lo) o.t_begin = *lo;
        o.t_end = hi;
    }
    o.fps = a.fps;
    o.bodies = a.body;
    o.world = !a.no_world;
    const bool bvh = a.format == "bvh";
    const crowd::Record record = crowd::load_record(a.record);
    const std::string graph_file = a.graph.empty() ? crowd::record_graph_file(record) : a.graph;
    auto graph = std::make_shared<crowd::MotionGraph>(crowd::load_graph(graph_file));
    const auto t_start = std::chrono::steady_clock::now();
    crowd::PoseBlend blend;
    blend.window = a.blend;
    crowd::FootLock lock;
    lock.on = !a.free_feet;
    auto sources = std::make_shared<crowd::PoseSources>(graph);
    std::unique_ptr<crowd::CrowdPoser> poser;
    try {
        poser = std::make_unique<crowd::CrowdPoser>(
            record, sources, a.joints == "major" ? crowd::RigJoints::Major : crowd::RigJoints::All, blend, lock);
    } catch (const crowd::GraphError& e) {
        throw InputError(a.record + ": " + e.what());
    } catch (const std::out_of_range& e) {
        throw InputError(a.record + ": " + e.what());
    }
    const io::ExportScene scene = crowd::crowd_scene(*poser, o);
    std::uintmax_t bytes = 0;
    std::string where = a.out;
    if (bvh) {
        std::error_code ec;
        std::filesystem::create_directories(a.out, ec);
        if (!std::filesystem::is_directory(a.out)) throw InputError(a.out + ": cannot create the folder");
        for (std::size_t k = 0; k < scene.skeletons.size(); ++k) {
            const std::string file =
                (std::filesystem::path(a.out) / ("agent_" + std::to_string(o.agent_begin + int(k)) + ".bvh")).string();
            bytes += io::write_bvh(scene, int(k), file);
        }
        where = a.out + "/agent_*.bvh";
    } else {
        bytes = io::write_gltf(scene, a.out);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    out << where << ": " << scene.skeletons.size() << " agents x " << scene.frames << " frames at "
        << std::setprecision(4) << 1.0 / scene.dt << " fps, " << scene.rig.names.size() << " joints, " << bytes
        << " bytes, " << std::fixed << std::setprecision(2) << seconds << " s\n";
    if (a.jumps) {
        std::vector<int> agents;
        for (std::size_t k = 0; k < scene.skeletons.size(); ++k) agents.push_back(o.agent_begin + int(k));
        const auto k0 = std::int64_t(std::llround(scene.start / record.dt));
        const auto k1 = k0 + std::int64_t(std::llround((scene.frames - 1) * scene.dt / record.dt)) + 1;
        const crowd::MotionMetrics j = crowd::motion_metrics(*poser, agents, k0, k1).blended;
        out << std::setprecision(4)
            << "pose jumps p99 (largest joint move relative to the root per frame, m): " << j.jump_start.p99 << " at "
            << j.jump_start.count << " clip starts, " << j.jump_within.p99 << " within clips (" << j.jump_within.count
            << " frames), ratio " << j.jump_ratio() << "\n";
    }
}

}  // namespace

void add_export_commands(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand(
        "export-crowd",
        "Write a crowd record's agents as animated skeletons: glTF / GLB (one armature per agent) or BVH");
    auto a = std::make_shared<ExportArgs>();
    cmd->add_option("RECORD", a->record, "Crowd record (mobb crowd --record)")->required();
    cmd->add_option("--out", a->out, "FILE.glb or FILE.gltf; with --format bvh a folder (one agent_K.bvh per agent)")
        ->required();
    cmd->add_option("--format", a->format, "gltf (default; .glb binary or .gltf text by --out) or bvh")
        ->check(CLI::IsMember({"gltf", "bvh"}));
    cmd->add_option("--agents", a->agents, "Agents A:B (A included, B not; default all)");
    cmd->add_option("--time", a->time, "Seconds A:B of the record (default: all of it)");
    cmd->add_option("--fps", a->fps, "Frames per second written (default: the record's)")->check(CLI::PositiveNumber);
    cmd->add_option("--joints", a->joints,
                    "all (every joint all sources share) or major (pelvis, legs, spine, head, arms)")
        ->check(CLI::IsMember({"all", "major"}))
        ->capture_default_str();
    cmd->add_option("--blend", a->blend, "Seconds over which a clip start eases out of the previous clip (0: none)")
        ->check(CLI::Range(0.0, 10.0))
        ->capture_default_str();
    cmd->add_flag("--free-feet", a->free_feet,
                  "Leave planted feet where the blended clips put them (default: locked where they came down)");
    cmd->add_flag("--body", a->body, "glTF: a skinned capsule per bone, so agents render as people");
    cmd->add_flag("--no-world", a->no_world, "glTF: leave out walls, obstacles and goals");
    cmd->add_flag("--jumps", a->jumps, "Also print the p99 joint jump at clip starts and within clips");
    cmd->add_option("--graph", a->graph, "Motion graph (default: the one the record names)");
    cmd->callback([a, &exit_code] { exit_code = guarded([&](std::ostream& out) { run_export(*a, out); }); });
}

}  // namespace mobb::app
