// Headless rendering through OSMesa: the same renderer (and optionally the same panels) as the window.
#pragma once
#include <string>
#include <vector>

#include "disk_layer.h"
#include "draw_counts.h"
#include "image.h"
#include "panels.h"
#include "state.h"

namespace mobb::viewer {

/// A rectangle of the image (pixels from its top-left corner) and what stands there: a label's text, a
/// window's name.
struct ImageRect {
    std::string name;
    Rect rect;
};

struct HeadlessOptions {
    int width = 960, height = 540;
    bool ui = false;    ///< also draw the ImGui panels
    bool help = false;  ///< with ui: the Shortcuts window open too
    /// With ui: the panels' state to start from (open panels, picks, camera requests such as frame all,
    /// which use the viewport the columns leave); null: default_panels() of the state.
    const Ui* start = nullptr;
    /// With ui: receives one line per window whose text does not fit ("Trace: 12 px too narrow") or
    /// that reaches past the image.
    std::vector<std::string>* cut = nullptr;
    /// Receives the 3D view's labels as drawn, their text and box.
    std::vector<ImageRect>* labels = nullptr;
    /// With ui: receives the panels' windows as drawn (menu bar, tooltips and popups left out).
    std::vector<ImageRect>* windows = nullptr;
};

/// Renders the state into an image. Throws std::runtime_error when no context can be made.
render::Image render_headless(State& state, const HeadlessOptions& options);

/// What bench_headless measured: frames per second, and what the last frame drew.
struct BenchResult {
    double fps = 0;
    render::DiskStats disks;
    render::DrawCounts draws;
};

/// Frames per second of the state's scene at width x height (a few warm-up frames, then `frames`).
BenchResult bench_headless(State& state, int width, int height, int frames);

}  // namespace mobb::viewer
