// What the window keeps between runs, in ImGui's ini file in the user's config folder: the panels the
// user opened or closed, the columns' widths, and the camera of each scene or file set.
#pragma once
#include <map>
#include <string>

#include "camera.h"
#include "panels.h"

namespace mobb::viewer {

/// $XDG_CONFIG_HOME/mobb/imgui.ini, else $HOME/.config/mobb/imgui.ini; empty when neither is set.
std::string settings_file();

struct ViewSettings {
    std::map<std::string, render::Camera> cameras;  ///< by scene key (a scene file, the clip files, a record)
    std::map<std::string, bool> panel_choices;      ///< Ui::panel_choices
    Columns columns;
};

/// Registers the [Mobb] sections with the current ImGui context; `settings` must outlive it.
void add_settings_handler(ViewSettings& settings);

/// The camera as one ini line's value ("target=x,y,z yaw=.. pitch=.. distance=.. fov=..") and back.
std::string camera_line(const render::Camera& camera);
bool parse_camera_line(const std::string& line, render::Camera& camera);

}  // namespace mobb::viewer
