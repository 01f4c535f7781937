// Motion graph: clips cut from mocap at transition points, joined where poses match (Kovar, Gleicher and
// Pighin 2002; Gleicher et al.'s Snap-Together Motion). The crowd of the paper's section 5 plays its clips.
#pragma once
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "mobb/core/path.h"

namespace mobb::crowd {

/// A graph file that cannot be read or makes no sense: "FILE: PLACE: message", one line.
class GraphError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// One input file as the graph used it.
struct GraphSource {
    std::string file;     ///< relative to the data folder (io::data_dir()) when inside it, else as given
    int frame_begin = 0;  ///< file frames dropped at the start (a stray T-pose frame: root jump > trim_jump)
    int samples = 0;      ///< samples after trimming and resampling to the graph's fps
};

/// A clip: samples [first, exit) of one source at the graph's dt. Its "last pose" is sample `exit`,
/// the pose at which a successor starts (in the same source when cut there, or a matching pose
/// elsewhere), so a clip holds exit - first samples and lasts (exit - first) * dt seconds.
struct GraphClip {
    int source = 0;
    int first = 0, exit = 0;              ///< sample indices at the graph's fps
    int frame_first = 0, frame_exit = 0;  ///< the same, as frames of the file
    /// The path in the clip's own frame: root at sample `first` at the origin, its heading along +x
    /// (heading: see PoseTrack). Metres.
    Path path;
    /// Root position and heading change (radians, counter-clockwise) of sample `exit` in that frame:
    /// where and how a successor starts.
    double exit_x = 0, exit_y = 0, exit_heading = 0;
    std::vector<int> successors;    ///< clip ids
    std::vector<double> distances;  ///< pose distance (metres) of each edge, below the threshold
};

struct MotionGraph {
    double fps = 30;                  ///< every clip shares dt = 1 / fps
    double threshold = 0;             ///< pose distance (metres, RMS) for transitions and edges
    int window = 5;                   ///< frames in a pose-distance window
    std::vector<std::string> joints;  ///< joint names compared (first source's skeleton)
    std::string command;              ///< the command that built it
    std::vector<GraphSource> sources;
    std::vector<GraphClip> clips;
    int transitions = 0;  ///< transition points found (build statistics)
    int clips_cut = 0;    ///< clips before keeping the largest strongly connected part

    double dt() const { return 1.0 / fps; }
    /// Placement of a successor of `clip` placed at p: chained through its exit transform; starts at
    /// p.t0 + samples * dt (the caller may recompute t0 on the global frame grid).
    Placement next(const Placement& p, int clip) const;
};

struct GraphBuildOptions {
    double fps = 30;          ///< resample every input (the paper's clips: 63 frames in 2.1 s)
    double threshold = 0.12;  ///< metres, RMS pose distance
    int window = 5;           ///< frames
    double min_clip = 1.0, max_clip = 4.0, target_clip = 2.0;  ///< clip lengths, seconds
    double trim_jump = 0.5;  ///< drop frame 0 when the root jumps more than this (metres) to frame 1
    int hubs = 2;            ///< hub poses whose matches are the transition points (Snap-Together Motion)
};

/// Builds the graph: pose distances between all frames of all inputs; hub poses chosen greedily (the
/// frame whose matches add the most new cut candidates, as Snap-Together Motion's common poses); the
/// transition points are the local minima, along each input, of the distance to a hub that are under
/// the threshold; clips cut between them (dynamic programming for lengths near target_clip, cutting
/// elsewhere only when needed); edges where the exit pose of one clip is within the threshold of the
/// first pose of another; and the largest strongly connected component. Throws io::LoadError for a bad
/// file, GraphError when nothing connects. Progress lines go to `log` when not null.
MotionGraph build_motion_graph(const std::vector<std::string>& files, const GraphBuildOptions& options,
                               std::ostream* log = nullptr);

/// The committed graph: assets/graphs/cmu_locomotion.json under the working directory if it exists,
/// else in the source tree this was built from.
std::string default_graph_file();

/// JSON of a graph (person-readable: one clip per object, a path sample per line) and back.
std::string graph_to_text(const MotionGraph& graph);
MotionGraph graph_from_json(const nlohmann::json& j, const std::string& where);
/// Reads and validates a graph file. Throws GraphError "FILE: ..." on any problem.
MotionGraph load_graph(const std::string& file);
void save_graph(const MotionGraph& graph, const std::string& file);

}  // namespace mobb::crowd
