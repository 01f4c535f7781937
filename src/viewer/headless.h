// Headless rendering through OSMesa: the same renderer (and optionally the same panels) as the window.
#pragma once
#include <string>

#include "disk_layer.h"
#include "image.h"
#include "state.h"

namespace mobb::viewer {

struct HeadlessOptions {
    int width = 960, height = 540;
    bool ui = false;    ///< also draw the ImGui panels
    bool help = false;  ///< with ui: the Shortcuts window open too
};

/// Renders the state into an image. Throws std::runtime_error when no context can be made.
render::Image render_headless(State& state, const HeadlessOptions& options);

/// Frames per second of the state's scene at width x height (a few warm-up frames, then `frames`).
double bench_headless(State& state, int width, int height, int frames, render::DiskStats* disks = nullptr);

}  // namespace mobb::viewer
