// The Scene panel: the layers drawn, the disk and box colourings, time cursor and window, the camera
// presets, and saving the scene to a file.
#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "layout.h"
#include "panels.h"
#include "scene.h"

namespace mobb::viewer {

namespace {

int max_level(const State& s) {
    int depth = 1;
    for (const LoadedClip& c : s.clips) depth = std::max(depth, c.tree->depth());
    return depth - 1;
}

double max_time(const State& s) {
    double t = 1.0;
    for (std::size_t k = 0; k < s.clips.size(); ++k)
        t = std::max(t, s.places[k].t0 + s.clips[k].tree->path().duration());
    return t;
}

bool drag(const char* label, double* v, float speed, double lo, double hi, const char* format) {
    return ImGui::DragScalar(label, ImGuiDataType_Double, v, speed, &lo, &hi, format);
}

/// The disk and box colourings (colour maps with a colour bar); a box colouring shows the boxes.
void colouring_combos(render::Layers& l) {
    const char* disks[render::kDiskColours];
    const char* boxes[render::kBoxColours];
    for (int k = 0; k < render::kDiskColours; ++k) disks[k] = to_string(render::DiskColour(k));
    for (int k = 0; k < render::kBoxColours; ++k) boxes[k] = to_string(render::BoxColour(k));
    int d = int(l.disk_colour), b = int(l.box_colour);
    if (ImGui::Combo("disks by", &d, disks, render::kDiskColours)) l.disk_colour = render::DiskColour(d);
    if (ImGui::Combo("boxes by", &b, boxes, render::kBoxColours)) {
        l.box_colour = render::BoxColour(b);
        if (l.box_colour != render::BoxColour::Level) l.boxes = true;
    }
}

void layer_checkboxes(State& s) {
    render::Layers& l = s.scene.layers;
    ImGui::Checkbox("grid", &l.grid);
    ImGui::SameLine();
    ImGui::Checkbox("labels", &l.labels);
    ImGui::Checkbox("disks", &l.disks);
    ImGui::SameLine();
    ImGui::Checkbox("translucent", &l.disks_translucent);
    ImGui::Checkbox("boxes", &l.boxes);
    ImGui::SameLine();
    ImGui::Checkbox("faces", &l.box_faces);
    ImGui::SameLine();
    ImGui::Checkbox("all", &l.all_levels);
    ImGui::SliderInt("level", &l.level, 0, max_level(s));
    ImGui::Checkbox("cursor", &l.cursor);
    ImGui::SameLine();
    ImGui::Checkbox("skeletons", &l.skeletons);
    ImGui::SameLine();
    ImGui::Checkbox("trace", &l.trace);
    ImGui::Checkbox("skeletons as bodies", &l.bodies);  // crowd agents: a capsule per bone
}

void camera_buttons(Ui& ui) {
    if (ImGui::Button("frame all (F)")) ui.request_frame_all = true;
    ImGui::SameLine();
    if (ImGui::Button("top")) ui.request_view = ViewPreset::Top;
    ImGui::SameLine();
    if (ImGui::Button("side")) ui.request_view = ViewPreset::Side;
    ImGui::SameLine();
    if (ImGui::Button("?")) ui.show_help = !ui.show_help;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("shortcuts (F1)");
}

}  // namespace

void save_to_path(State& s, Ui& ui) {
    try {
        sync_scene(s);
        save_scene(s.scene, ui.save_path);
        ui.status = "saved " + ui.save_path;
    } catch (const std::exception& e) {
        ui.status = e.what();
    }
}

void scene_panel(State& s, Ui& ui) {
    if (!begin_panel(s, ui, &PanelsOpen::scene)) return;
    layer_checkboxes(s);
    colouring_combos(s.scene.layers);
    drag("time", &s.scene.cursor, 0.01f, 0.0, max_time(s), "%.2f s");
    drag("window", &s.scene.window, 0.05f, 0.0, max_time(s), s.scene.window > 0 ? "+-%.2f s" : "all time");
    drag("m per s", &s.scene.time_scale, 0.01f, kMinTimeScale, kMaxTimeScale, "%.2f");
    drag("skeleton", &s.scene.skeleton_scale, 0.01f, kMinSkeletonScale, kMaxSkeletonScale, "%.2f x");
    camera_buttons(ui);
    char path[256];
    std::snprintf(path, sizeof path, "%s", ui.save_path.c_str());
    if (ImGui::InputText("##path", path, sizeof path)) ui.save_path = path;
    ImGui::SameLine();
    if (ImGui::Button("save")) save_to_path(s, ui);
    if (!ui.status.empty()) ImGui::TextWrapped("%s", ui.status.c_str());
    ImGui::End();
}

}  // namespace mobb::viewer
