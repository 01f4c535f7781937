// The interactive window: GLFW + ImGui around the shared renderer.
#pragma once
#include <string>

#include "state.h"

namespace mobb::viewer {

struct WindowOptions {
    int width = 1280, height = 800;
    int frames = 0;          ///< > 0: close after this many frames (smoke tests)
    std::string screenshot;  ///< when set: save the last frame's framebuffer here
    std::string scene_file;  ///< the default path of "save"
};

/// Runs until the window closes. Throws std::runtime_error when no window can be opened.
void run_window(State& state, const WindowOptions& options);

}  // namespace mobb::viewer
