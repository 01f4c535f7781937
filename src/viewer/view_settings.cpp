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

// sscanf reads the settings file the viewer wrote itself (camera_line, write_all), so cert-err34-c (sscanf
// cannot report a number out of range) is off for these reads: only a hand edit puts one there.
bool parse_camera_line(const std::string& line, render::Camera& camera) {
    render::Camera c;
    // NOLINTNEXTLINE(cert-err34-c): see above
    if (std::sscanf(line.c_str(), "target=%f,%f,%f yaw=%f pitch=%f distance=%f fov=%f", &c.target.x, &c.target.y,
                    &c.target.z, &c.yaw, &c.pitch, &c.distance, &c.fov) != 7)
        return false;
    if (!(c.distance > 0) || !(c.fov > 0 && c.fov < 180)) return false;
    camera = c;
    return true;
}

namespace {

// Entries: [Mobb][Panel choices] with a "name=0|1" line per panel the user opened or closed, [Mobb][Columns]
// with the columns' widths and collapsed flags, and [Mobb][Camera KEY] with a camera line. (Older files'
// [Mobb][Panels] listed every panel; it is ignored, so that each kind of file opens its own panels.)
void* read_open(ImGuiContext*, ImGuiSettingsHandler* h, const char* name) {
    auto& s = *static_cast<ViewSettings*>(h->UserData);
    if (std::strcmp(name, "Panel choices") == 0) return &s.panel_choices;
    if (std::strcmp(name, "Columns") == 0) return &s.columns;
    if (std::strncmp(name, "Camera ", 7) == 0) return &s.cameras[name + 7];
    return nullptr;
}

void read_choice(std::map<std::string, bool>& choices, const char* line) {
    for (const PanelInfo& p : panel_list()) {
        const std::size_t n = std::strlen(p.name);
        if (std::strncmp(line, p.name, n) == 0 && line[n] == '=') choices[p.name] = line[n + 1] == '1';
    }
}

void read_columns(Columns& c, const char* line) {
    float w = 0;
    int flag = 0;
    // NOLINTBEGIN(cert-err34-c): as in parse_camera_line
    if (std::sscanf(line, "left=%f", &w) == 1 && w > 0) c.left = w;
    if (std::sscanf(line, "right=%f", &w) == 1 && w > 0) c.right = w;
    if (std::sscanf(line, "left_collapsed=%d", &flag) == 1) c.left_collapsed = flag != 0;
    if (std::sscanf(line, "right_collapsed=%d", &flag) == 1) c.right_collapsed = flag != 0;
    if (std::sscanf(line, "bottom_collapsed=%d", &flag) == 1) c.bottom_collapsed = flag != 0;
    // NOLINTEND(cert-err34-c)
}

void read_line(ImGuiContext*, ImGuiSettingsHandler* h, void* entry, const char* line) {
    auto& s = *static_cast<ViewSettings*>(h->UserData);
    if (entry == &s.panel_choices) return read_choice(s.panel_choices, line);
    if (entry == &s.columns) return read_columns(s.columns, line);
    parse_camera_line(line, *static_cast<render::Camera*>(entry));
}

void write_all(ImGuiContext*, ImGuiSettingsHandler* h, ImGuiTextBuffer* out) {
    const auto& s = *static_cast<const ViewSettings*>(h->UserData);
    out->appendf("[%s][Panel choices]\n", h->TypeName);
    for (const auto& [name, open] : s.panel_choices) out->appendf("%s=%d\n", name.c_str(), open ? 1 : 0);
    const Columns& c = s.columns;
    out->appendf(
        "\n[%s][Columns]\nleft=%.0f\nright=%.0f\nleft_collapsed=%d\nright_collapsed=%d\nbottom_collapsed=%d\n\n",
        h->TypeName, double(c.left), double(c.right), c.left_collapsed ? 1 : 0, c.right_collapsed ? 1 : 0,
        c.bottom_collapsed ? 1 : 0);
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
