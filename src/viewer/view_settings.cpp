#include "view_settings.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <imgui.h>
#include <imgui_internal.h>

namespace mobb::viewer {

std::string settings_file() {
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::string(x) + "/mobb/imgui.ini";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.config/mobb/imgui.ini";
    return {};
}

std::string camera_line(const render::Camera& c) {
    char line[256];
    std::snprintf(line, sizeof line, "target=%.6g,%.6g,%.6g yaw=%.6g pitch=%.6g distance=%.6g fov=%.6g", c.target.x,
                  c.target.y, c.target.z, c.yaw, c.pitch, c.distance, c.fov);
    return line;
}

bool parse_camera_line(const std::string& line, render::Camera& camera) {
    render::Camera c;
    if (std::sscanf(line.c_str(), "target=%f,%f,%f yaw=%f pitch=%f distance=%f fov=%f", &c.target.x, &c.target.y,
                    &c.target.z, &c.yaw, &c.pitch, &c.distance, &c.fov) != 7)
        return false;
    if (!(c.distance > 0) || !(c.fov > 0 && c.fov < 180)) return false;
    camera = c;
    return true;
}

namespace {

// Entries: [Mobb][Panels] with one "name=0|1" line per panel, and [Mobb][Camera KEY] with a camera line.
void* read_open(ImGuiContext*, ImGuiSettingsHandler* h, const char* name) {
    auto& s = *static_cast<ViewSettings*>(h->UserData);
    if (std::strcmp(name, "Panels") == 0) {
        s.panels_read = true;
        return &s.panels;
    }
    if (std::strncmp(name, "Camera ", 7) == 0) return &s.cameras[name + 7];
    return nullptr;
}

void read_line(ImGuiContext*, ImGuiSettingsHandler* h, void* entry, const char* line) {
    auto& s = *static_cast<ViewSettings*>(h->UserData);
    if (entry == &s.panels) {
        for (const PanelInfo& p : panel_list()) {
            const std::size_t n = std::strlen(p.name);
            if (std::strncmp(line, p.name, n) == 0 && line[n] == '=') s.panels.*p.open = line[n + 1] == '1';
        }
        return;
    }
    parse_camera_line(line, *static_cast<render::Camera*>(entry));
}

void write_all(ImGuiContext*, ImGuiSettingsHandler* h, ImGuiTextBuffer* out) {
    const auto& s = *static_cast<const ViewSettings*>(h->UserData);
    out->appendf("[%s][Panels]\n", h->TypeName);
    for (const PanelInfo& p : panel_list()) out->appendf("%s=%d\n", p.name, s.panels.*p.open ? 1 : 0);
    out->append("\n");
    for (const auto& [key, camera] : s.cameras)
        out->appendf("[%s][Camera %s]\n%s\n\n", h->TypeName, key.c_str(), camera_line(camera).c_str());
}

}  // namespace

void add_settings_handler(ViewSettings& settings) {
    ImGuiSettingsHandler h;
    h.TypeName = "Mobb";
    h.TypeHash = ImHashStr("Mobb");
    h.ReadOpenFn = read_open;
    h.ReadLineFn = read_line;
    h.WriteAllFn = write_all;
    h.UserData = &settings;
    ImGui::GetCurrentContext()->SettingsHandlers.push_back(h);
}

}  // namespace mobb::viewer
