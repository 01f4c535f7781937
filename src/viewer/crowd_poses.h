// Skeletons of a recorded crowd at the time cursor. An agent at time t plays one graph clip; its pose
// is the clip's source frame at that instant, moved into the clip's own frame by the same rigid 2D
// motion the graph applied to the root path (source root at sample `first` to the origin, heading to
// +x), then by the clip's world placement. Sources are loaded once, on first use.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "frame.h"
#include "mobb/crowd/motion_graph.h"
#include "mobb/crowd/record.h"
#include "mobb/io/load.h"

namespace mobb::viewer {

/// One source as the skeletons need it: the animation, and per sample the root and heading the graph
/// used to localise clips (crowd::pose_track), plus the lowest joint height (the skeleton's feet).
struct PoseSource {
    std::shared_ptr<const io::Clip> clip;  ///< null when it could not be loaded (see error)
    std::vector<double> root_x, root_y, heading;
    double floor = 0.0;
    std::string error;
};

/// Rigid motion from source ground coordinates to the world for graph clip `clip` placed at `place`
/// (t0 is kept): world = place o (rotate by -heading[first], root[first] to the origin).
Placement source_to_world(const PoseSource& source, const crowd::GraphClip& clip, const Placement& place);

/// The clip agent `agent` plays at time t and the source sample showing it. False outside its clips.
struct AgentClipAt {
    const crowd::PlacedClip* placed = nullptr;
    int sample = 0;  ///< sample index in the source (graph fps)
};
bool agent_clip_at(const crowd::Record& record, const crowd::MotionGraph& graph, int agent, double t, AgentClipAt& out);

/// Every source of one graph, each loaded on first use and kept (a failure too, with its reason, so a
/// missing file is not retried every frame).
class PoseSources {
public:
    explicit PoseSources(std::shared_ptr<const crowd::MotionGraph> graph) : graph_(std::move(graph)) {}
    const PoseSource& get(int source);
    /// The first load failure met so far ("" when none): what the crowd panel shows.
    const std::string& error() const { return error_; }
    int loaded() const;

private:
    std::shared_ptr<const crowd::MotionGraph> graph_;
    std::vector<std::unique_ptr<PoseSource>> sources_;
    std::string error_;
};

/// The skeleton of every agent at time t (agents whose source failed are left out), coloured per agent.
std::vector<render::PosedSkeleton> crowd_skeletons(const crowd::Record& record, const crowd::MotionGraph& graph,
                                                   PoseSources& sources, double t,
                                                   const std::vector<glm::vec3>& agent_colors);

}  // namespace mobb::viewer
