// A motion graph's clips: their kinds, where a clip leaves its successor, their sources. Building a
// graph from mocap: motion_graph_build.cpp; its file (reading, checking, writing): motion_graph_file.cpp.
#include "mobb/crowd/graph/motion_graph.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mobb/io/load.h"

namespace mobb::crowd {

double root_reach_of(const GraphClip& c) {
    const glm::dvec2 o = root_at(c, 0);
    double d = 0;
    for (std::size_t i = 0; i < c.path.size(); ++i) {
        const glm::dvec2 p = root_at(c, i);
        d = std::max(d, std::hypot(p.x - o.x, p.y - o.y));
    }
    return d;
}

ClipKind kind_of(const GraphClip& c, int id) {
    const double reach = root_reach_of(c), exit = std::hypot(c.exit_x, c.exit_y);
    const bool loops = std::find(c.successors.begin(), c.successors.end(), id) != c.successors.end();
    if (loops && reach <= kIdleReach && c.exit_x == 0 && c.exit_y == 0 && c.exit_heading == 0) return ClipKind::Idle;
    if (reach <= kInPlaceReach && exit <= kInPlaceExit) return ClipKind::InPlace;
    return exit / c.path.duration() < kWalking ? ClipKind::Slow : ClipKind::Walk;
}

std::vector<ClipKind> kinds_of(const MotionGraph& graph) {
    std::vector<ClipKind> kinds;
    for (std::size_t c = 0; c < graph.clips.size(); ++c) kinds.push_back(kind_of(graph.clips[c], int(c)));
    return kinds;
}

const char* to_string(ClipKind kind) {
    switch (kind) {
        case ClipKind::Walk: return "walk";
        case ClipKind::Slow: return "slow";
        case ClipKind::InPlace: return "in place";
        case ClipKind::Idle: return "idle";
    }
    return "?";
}

Placement MotionGraph::next(const Placement& p, int clip) const { return next(p, Rigid2::of(p), clip); }

io::Clip load_graph_source(const MotionGraph& g, int source) {
    const GraphSource& src = g.sources.at(std::size_t(source));
    // Frames dropped first, then resampled (LoadOptions applies them in that order), as the build did.
    io::LoadOptions lo;
    lo.fps = g.fps;
    lo.frame_begin = src.frame_begin;
    lo.frame_end = src.frame_end;
    const std::string file = io::resolve_data_file(src.file);
    io::Clip clip = io::load_clip(file, lo);
    if (int(clip.path.size()) != src.samples)
        throw GraphError(file + ": " + std::to_string(clip.path.size()) + " samples at " + std::to_string(g.fps) +
                         " fps, the graph expects " + std::to_string(src.samples) + " (a different file?)");
    return clip;
}

std::string default_graph_file() {
    std::string local = "assets/graphs/cmu_locomotion.json";
    if (std::filesystem::exists(local)) return local;
    return std::string(MOBB_SOURCE_DIR) + "/" + local;
}

}  // namespace mobb::crowd
