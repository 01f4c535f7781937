// The viewer's model: a scene, its loaded clips and trees, the query's answer and trace. Shared by
// the window, headless rendering and glTF export; the panels edit it.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "camera.h"
#include "colouring.h"
#include "frame.h"
#include "mobb/core/clearance.h"
#include "mobb/core/query.h"
#include "mobb/core/trace.h"
#include "mobb/core/tree.h"
#include "mobb/io/load.h"
#include "scene.h"

namespace mobb::viewer {

struct CrowdView;  // crowd_view.h

struct LoadedClip {
    std::string name;                ///< file name, or "walk N"
    std::shared_ptr<io::Clip> clip;  ///< null for synthetic paths (no skeleton)
    std::unique_ptr<Tree> tree;      ///< built with the scene's tree options
    bool hidden = false;             ///< not drawn: a crowd's agent out of the run in the frames at hand
};

struct State {
    Scene scene;
    std::vector<LoadedClip> clips;  ///< scene.clips, then the generated walks
    std::vector<Placement> places;  ///< one per clip (generated ones too)
    Trace trace;
    QueryStats stats;
    SamplePair hit;
    bool answer = false;
    bool queried = false;
    std::vector<ClearanceSample> clearance;  ///< of the query's clips A and B over time (core clearance())
    render::Camera camera;
    std::uint64_t revision = 1;  ///< bumped on any change of clips, placements or trees
    /// A recorded crowd (mobb view --crowd): clip k's path is fixed_paths[k] when k < its size, and
    /// its colour colors[k] when k < that size. Empty for scenes.
    std::shared_ptr<CrowdView> crowd;
    std::vector<Path> fixed_paths;
    std::vector<glm::vec3> colors;
    /// The disk and box colourings' values, filled by frame_of() when first needed (shared, not copied).
    std::shared_ptr<Colouring> colouring = std::make_shared<Colouring>();
};

/// Loads every clip and builds the trees, runs the query, sets the camera. Throws io::LoadError or
/// ViewerError naming the file.
State load_state(const Scene& scene, float aspect);

/// Opens a BVH / glTF file as one more scene clip (after the scene's clips, before generated walks) at
/// the origin, builds its tree and, when the query lacks a clip, makes it the query's A or B. Returns
/// its index. Throws io::LoadError naming the file (also for a crowd record's state); the state is
/// unchanged then.
int add_clip_file(State& state, const std::string& file);

void rebuild_trees(State& state);  ///< after tree options change; also re-runs the query
void run_query(State& state);      ///< after placements or the query's clips change
void frame_all(State& state, float aspect);
/// Keeps yaw and pitch and frames the world rectangle [x0, x1] x [y0, y1] (metres) over the time window
/// round the cursor (all time when the window is 0): a door and its queue rather than the whole world.
void frame_region(State& state, double x0, double y0, double x1, double y1, float aspect);
void sync_scene(State& state);  ///< copies placements and camera back into state.scene (to save)

/// The step actually shown: scene.step clamped to the trace (-1 when none).
int shown_step(const State& state);

/// What the renderer draws. For a crowd it also poses every agent's skeleton at the cursor, loading
/// the mocap sources it needs the first time (through state.crowd, which is shared, not copied).
render::Frame frame_of(const State& state);

}  // namespace mobb::viewer
