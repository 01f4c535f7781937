// Motion graph: clips cut from mocap at transition points, joined where poses match (Kovar, Gleicher and
// Pighin 2002; Gleicher et al.'s Snap-Together Motion). The crowd of the paper's section 5 plays its clips.
#pragma once
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <nlohmann/json_fwd.hpp>

#include "mobb/core/path.h"
#include "mobb/io/load.h"

namespace mobb::crowd {

/// A graph file that cannot be read or makes no sense: "FILE: PLACE: message", one line.
class GraphError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// One input file as the graph used it.
struct GraphSource {
    std::string file;     ///< relative to the data folder (io::data_dir()) when inside it, else as given
    int frame_begin = 0;  ///< file frames dropped at the start (a stray T-pose frame: root jump > trim_jump,
                          ///< or the range asked for)
    int frame_end = -1;   ///< the range asked for ends before this file frame; -1: the file's end
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
    /// (heading: see PoseTrack). Metres. Its disks are centred as the graph's `centre` says: on the root
    /// (the first sample then at the origin) or on the smallest disk holding the body.
    Path path;
    /// The root on the ground at each sample, in the clip's frame (metres, the first at the origin), when the
    /// disks are not centred on it; empty: the path's centres are the root (root_at).
    std::vector<glm::dvec2> root;
    /// Root position and heading change (radians, counter-clockwise) of sample `exit` in that frame:
    /// where and how a successor starts.
    double exit_x = 0, exit_y = 0, exit_heading = 0;
    std::vector<int> successors;    ///< clip ids
    std::vector<double> distances;  ///< pose distance (metres) of each edge, below the threshold
    /// An idle clip (ClipKind::Idle) loops in place: its exit is snapped to the identity, and this is
    /// how far its root really moved (metres) and turned (radians) over the clip in its take.
    double idle_drift = 0, idle_turn = 0;
};

/// What a clip does, from its root's reach and its exit alone (kind_of).
enum class ClipKind {
    Walk,     ///< moves: from its start to its exit at least kWalking metres per second
    Slow,     ///< moves slower: starting, stopping
    InPlace,  ///< the root stays within kInPlaceReach of its start and the next clip starts within kInPlaceExit
    Idle,     ///< stands still and loops on itself: in place, within kIdleReach, a successor of itself, exit
              ///< snapped to the identity by the graph's builder - the ground an agent holds (escape.h)
};
inline constexpr double kWalking = 0.6;                            // metres per second
inline constexpr double kInPlaceReach = 0.25, kInPlaceExit = 0.2;  // metres
inline constexpr double kIdleReach = 0.15, kIdleExit = 0.05;       // metres (exit: before the snap)
inline constexpr double kIdleTurn = 0.1;                           // radians (before the snap)
ClipKind kind_of(const GraphClip& clip, int id);
/// The clip's root on the ground at sample i, in its frame (metres): where the agent is, whatever its disk.
inline glm::dvec2 root_at(const GraphClip& clip, std::size_t i) {
    return clip.root.empty() ? glm::dvec2(clip.path.samples[i].x, clip.path.samples[i].y) : clip.root[i];
}
/// The same placed by `m` (a placement's rigid part, Rigid2::of): the root in the world (metres).
inline glm::dvec2 placed_root(const GraphClip& clip, const Rigid2& m, std::size_t i) {
    const glm::dvec2 p = root_at(clip, i);
    return {m.apply_x(p.x, p.y), m.apply_y(p.x, p.y)};
}
/// The largest ground distance of the clip's root from where it starts (metres).
double root_reach_of(const GraphClip& clip);
const char* to_string(ClipKind kind);

/// The rates a graph may have (frames per second): those of motion capture.
inline constexpr double kMinGraphFps = 1, kMaxGraphFps = 1000;

struct MotionGraph {
    double fps = 30;                               ///< every clip shares dt = 1 / fps, kMinGraphFps..kMaxGraphFps
    double threshold = 0;                          ///< pose distance (metres, RMS) for transitions and edges
    int window = 5;                                ///< frames in a pose-distance window
    std::vector<std::string> joints;               ///< joint names compared (first source's skeleton)
    std::string command;                           ///< the command that built it
    io::PathCentre centre = io::PathCentre::Root;  ///< where the clips' disks are centred
    std::vector<GraphSource> sources;
    std::vector<GraphClip> clips;
    int transitions = 0;  ///< transition points found (build statistics)
    int clips_cut = 0;    ///< clips before keeping the largest strongly connected part

    double dt() const { return 1.0 / fps; }
    /// Placement of a successor of `clip` placed at p: chained through its exit transform; starts at
    /// p.t0 + samples * dt (the caller may recompute t0 on the global frame grid).
    Placement next(const Placement& p, int clip) const;
    /// The same with the placement's rotation evaluated once (m = Rigid2::of(p)), for many clips. Inline:
    /// the look-ahead places every clip it pushes with it.
    Placement next(const Placement& p, const Rigid2& m, int clip) const {
        const GraphClip& c = clips[std::size_t(clip)];
        return {p.x + m.c * c.exit_x - m.s * c.exit_y, p.y + m.s * c.exit_x + m.c * c.exit_y, p.theta + c.exit_heading,
                p.t0 + double(c.path.size()) * dt()};
    }
};

/// kind_of() of every clip of `graph`, by clip id.
std::vector<ClipKind> kinds_of(const MotionGraph& graph);

struct GraphBuildOptions {
    double fps = 30;          ///< resample every input (the paper's clips: 63 frames in 2.1 s); 1 to 1000
    double threshold = 0.12;  ///< metres, RMS pose distance
    int window = 5;           ///< frames
    double min_clip = 1.0, max_clip = 4.0, target_clip = 2.0;  ///< clip lengths, seconds
    double trim_jump = 0.5;  ///< drop frame 0 when the root jumps more than this (metres) to frame 1
    int hubs = 2;            ///< hub poses whose matches are the transition points (Snap-Together Motion)
    io::PathCentre centre = io::PathCentre::Root;  ///< --centre root|enclosing: the clips' disks
};

/// Builds the graph from inputs "FILE", or "FILE:A:B" for frames [A, B) of the file: pose distances
/// between all frames of all inputs; hub poses chosen greedily (the frame whose matches add the most new
/// cut candidates, as Snap-Together Motion's common poses); the transition points are the local minima,
/// along each input, of the distance to a hub that are under the threshold; clips cut between them
/// (dynamic programming for lengths near target_clip, cutting elsewhere only when needed); edges where
/// the exit pose of one clip is within the threshold of the first pose of another; the largest strongly
/// connected component; and idle clips (a standing stretch that follows itself, ClipKind) get the
/// identity as their exit, so they loop in place. Throws io::LoadError for a bad file, GraphError for a
/// bad range or when nothing connects. Progress lines go to `log` when not null.
MotionGraph build_motion_graph(const std::vector<std::string>& files, const GraphBuildOptions& options,
                               std::ostream* log = nullptr);

/// Source `source` of a graph loaded as the graph was built from it: its frame range, resampled to the
/// graph's fps. Throws io::LoadError naming the file, or GraphError when its sample count differs from
/// the graph's (a different file).
io::Clip load_graph_source(const MotionGraph& graph, int source);

/// The committed graph: assets/graphs/cmu_locomotion.json under the working directory if it exists,
/// else in the source tree this was built from.
std::string default_graph_file();

/// JSON of a graph (person-readable: one clip per object, a path sample per line) and back.
std::string graph_to_text(const MotionGraph& graph);
/// Every field is checked against what it means, and the first problem throws GraphError
/// "WHERE.FIELD: message" (one line): fps in kMinGraphFps..kMaxGraphFps (and dt, when given, 1 / fps);
/// threshold > 0; window >= 1; sources: frame_begin >= 0, frame_end -1 or after it, samples >= 1; per clip:
/// id its index, source in range, samples [first, exit] with 0 <= first < exit < the source's samples,
/// frames [first, exit] in order inside the source's range, exit within 1 km with a heading in [-pi, pi],
/// idle_snap only on an identity exit and within kIdleExit / kIdleTurn, successors existing clips listed
/// once, distances one per successor in [0, threshold], path exit - first samples within 1 km with
/// 0 <= r <= 10 m starting at the origin, duration its duration; stats (when given) what the clips add up
/// to. Integers must be integers; numbers finite.
MotionGraph graph_from_json(const nlohmann::json& j, const std::string& where);
/// Reads and validates a graph file (graph_from_json). Throws GraphError "FILE: graph...: ..." on any problem.
MotionGraph load_graph(const std::string& file);
void save_graph(const MotionGraph& graph, const std::string& file);

}  // namespace mobb::crowd
