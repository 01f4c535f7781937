// Scene files (JSON): which clips (files with loader options, or synthetic random walks), their
// placements, tree settings, the query, visible layers, time cursor, camera, trace step, image size.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "camera.h"
#include "frame.h"
#include "mobb/core/path.h"
#include "mobb/core/tree.h"
#include "mobb/io/load.h"

namespace mobb::viewer {

/// What a scene's numbers may be: the file's reader refuses anything else, and the panels' drags stay
/// within the same ranges (one place for both).
/// Metres from the origin (placements, the camera's target) and seconds from 0 (start times, the
/// cursor, the time window): the Query panel's drag range; the grid draws a line per metre across it.
inline constexpr double kFar = 1e4;
inline constexpr double kMinTimeScale = 0.05, kMaxTimeScale = 20;         ///< metres per second (Scene panel)
inline constexpr double kMinSkeletonScale = 0.05, kMaxSkeletonScale = 5;  ///< times the standing height
inline constexpr double kMinScale = 1e-6, kMaxScale = 1e3;                ///< a clip's metres per file unit (um to km)
inline constexpr double kMinRate = 1, kMaxRate = 1000;  ///< samples per second: a walk's hz, a clip's fps
inline constexpr double kMaxWalkSamples = 1e7;          ///< all random walks of a scene together
inline constexpr double kMaxCameraDistance = 1e6;       ///< metres from the target (floats stay finite)
inline constexpr double kMinFov = 1, kMaxFov = 170;     ///< degrees, vertical
inline constexpr double kMaxYaw = 1e6;                  ///< degrees either way (orbiting adds up)

/// A synthetic path: a seeded random walk (no skeleton), for data-free tests and the benchmark.
struct RandomWalk {
    double seconds = 10.0;
    double hz = 60.0;
    unsigned seed = 1;
};

struct SceneClip {
    std::string file;                ///< relative to the data folder (io::data_dir()) or absolute
    std::optional<RandomWalk> walk;  ///< instead of a file
    io::LoadOptionText load;         ///< loader options, as on the command line (up, scale, frames, fps)
    Placement place;                 ///< theta in radians (degrees in the file)
    bool visible = true;
};

/// `count` random walks on a square grid `spacing` metres apart (the benchmark crowd).
struct Generate {
    int count = 0;
    RandomWalk walk;
    double spacing = 8.0;
};

struct Scene {
    std::vector<SceneClip> clips;
    Generate generate;
    TreeOptions tree;
    int query_a = 0, query_b = 1;  ///< clip indices of the query; -1 for none
    int step = -1;                 ///< trace step shown (clamped to the last event); -1 for none
    render::Layers layers;
    double time_scale = 1.0;
    double cursor = 0.0;
    double window = 0.0;  ///< seconds either side of the cursor drawn (0: all time)
    double skeleton_scale = 0.5;
    std::optional<render::Camera> camera;  ///< absent: frame everything; target in space-time (x, y, t)
    int width = 960, height = 540;
    bool multisample = true;  ///< render::Frame::multisample; saved under "image" only when off
};

/// Parses a scene. Throws ViewerError with one line "FILE.KEY.PATH: message" (or "FILE: " and the JSON
/// parser's line and column) for a missing file, malformed JSON, unknown keys, wrong types, numbers out
/// of the ranges above and clip indices past the scene's clips. A query step past the trace's last is
/// its last (assets/scenes/trace_hit.json shows the hit so).
Scene load_scene(const std::string& file);
Scene parse_scene(const nlohmann::json& json, const std::string& file);
nlohmann::json scene_json(const Scene& scene);
/// Writes through a temporary file renamed into place. Throws ViewerError.
void save_scene(const Scene& scene, const std::string& file);

/// A scene of the given clip files, placed so that their paths cross at the origin.
Scene scene_of_files(const std::vector<std::string>& files);

}  // namespace mobb::viewer
