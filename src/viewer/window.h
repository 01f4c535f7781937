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
    /// Names what is shown (a scene file, the clip files, a crowd record): the settings file keeps
    /// the camera under it. Empty: the camera is neither restored nor kept.
    std::string settings_key;
    /// Frame everything in the viewport the panels leave at the first frame, unless the settings file
    /// restores a camera (the state's camera was framed for the whole window).
    bool frame_all = false;
};

/// Runs until the window closes. Throws std::runtime_error when no window can be opened.
void run_window(State& state, const WindowOptions& options);

}  // namespace mobb::viewer
