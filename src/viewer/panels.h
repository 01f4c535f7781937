// Dear ImGui panels: scene and layers, query debugger, trace list, tree fit, picked disk.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "mobb/core/tree.h"
#include "state.h"

namespace mobb::viewer {

/// A disk chosen by clicking in the 3D view.
struct Pick {
    int clip = -1;
    int sample = -1;
};

/// Per-level statistics of the three fits of one clip, for the tree-fit panel.
struct FitTable {
    int clip = -1;
    int n_min = 0;
    std::uint64_t revision = 0;
    std::vector<LevelStats> mobb, umobb, pca;
};

/// What the panels remember between frames (not part of a scene).
struct Ui {
    glm::ivec2 window_size{960, 540};
    bool playing = false;
    float rate = 8.0f;  ///< trace steps per second while playing
    double play_clock = 0.0;
    bool follow = true;  ///< move the time cursor to each trace step
    bool scroll_to_step = true;
    Pick pick;
    FitTable fit;
    std::string save_path = "scene.json";
    std::string status;  ///< last message (saved, errors)
    bool request_frame_all = false;
    int request_view = 0;    ///< 1 top, 2 side
    bool show_help = false;  ///< the Shortcuts window (F1 or ?)
};

/// The viewer's compact dark style (call once after ImGui::CreateContext).
void apply_style();

void draw_panels(State& state, Ui& ui);

/// Moves to trace step k (clamped) and, when following, puts the time cursor on it.
void go_to_step(State& state, Ui& ui, int k);
/// Advances the trace while playing.
void update_playback(State& state, Ui& ui, double seconds);

}  // namespace mobb::viewer
