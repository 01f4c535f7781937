#include "shortcuts.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "layout.h"

namespace mobb::viewer {

const std::vector<Shortcut>& shortcuts() {
    static const std::vector<Shortcut> table = {
        {GLFW_KEY_SPACE, false, false, Command::TogglePlay, "Space", "play / pause the trace"},
        {GLFW_KEY_RIGHT, false, true, Command::StepForward, "Right", "next trace step"},
        {GLFW_KEY_LEFT, false, true, Command::StepBack, "Left", "previous trace step"},
        {GLFW_KEY_HOME, false, false, Command::FirstStep, "Home", "first trace step"},
        {GLFW_KEY_END, false, false, Command::LastStep, "End", "last trace step"},
        {GLFW_KEY_F, false, false, Command::FrameAll, "F", "frame everything"},
        {GLFW_KEY_T, false, false, Command::TopView, "T", "view from the top (space-time seen along t)"},
        {GLFW_KEY_S, false, false, Command::SideView, "S", "view from the side"},
        {GLFW_KEY_O, false, false, Command::OpenFiles, "O", "open clip files (the Open panel)"},
        {GLFW_KEY_LEFT_BRACKET, false, false, Command::ToggleLeftColumn, "[", "collapse / expand the left column"},
        {GLFW_KEY_RIGHT_BRACKET, false, false, Command::ToggleRightColumn, "]", "collapse / expand the right column"},
        {GLFW_KEY_TAB, false, false, Command::ToggleColumns, "Tab",
         "collapse / expand the columns and the bottom strip"},
        {GLFW_KEY_ESCAPE, false, false, Command::ClearPicks, "Esc", "clear the picked disks (Inspector)"},
        {GLFW_KEY_Q, false, false, Command::Quit, "Q", "quit (the window's settings are kept)"},
        {GLFW_KEY_F1, false, false, Command::ToggleHelp, "F1", "show / hide this window"},
        {GLFW_KEY_SLASH, true, false, Command::ToggleHelp, "Shift+/ (?)", "show / hide this window"},
    };
    return table;
}

const Shortcut* find_shortcut(int key, bool shift, bool repeat) {
    for (const Shortcut& k : shortcuts())
        if (k.key == key && k.shift == shift && (!repeat || k.repeat)) return &k;
    return nullptr;
}

const std::vector<Gesture>& gestures() {
    static const std::vector<Gesture> table = {
        {"drag", "orbit"},
        {"Shift+drag, middle drag", "pan"},
        {"wheel", "zoom"},
        {"click", "pick a disk (Inspector; two picks: ruler), select its trace events"},
        {"click a box", "(away from disks) select the trace events on its node"},
        {"drag a panel's side", "resize its column"},
        {"drop files", "open clip files (BVH, glTF, FBX, Collada, ...)"},
        {"Ctrl+drag", "move a clip on its ground plane (the query reruns)"},
    };
    return table;
}

void run_command(Command command, State& s, Ui& ui) {
    switch (command) {
        case Command::TogglePlay: ui.playing = !ui.playing; break;
        case Command::StepForward: go_to_step(s, ui, shown_step(s) + 1); break;
        case Command::StepBack: go_to_step(s, ui, shown_step(s) - 1); break;
        case Command::FirstStep: go_to_step(s, ui, 0); break;
        case Command::LastStep: go_to_step(s, ui, int(s.trace.size()) - 1); break;
        case Command::OpenFiles: choose_panel(ui, &PanelsOpen::open, !ui.panels.open); break;
        case Command::ToggleLeftColumn: toggle_column(ui, Column::Left); break;
        case Command::ToggleRightColumn: toggle_column(ui, Column::Right); break;
        case Command::ToggleColumns: toggle_columns(ui); break;
        case Command::ClearPicks:
            ui.pick = ui.ruler = {};
            ui.picked_events.clear();
            break;
        case Command::Quit: ui.request_quit = true; break;
        case Command::FrameAll: ui.request_frame_all = true; break;
        case Command::TopView: ui.request_view = ViewPreset::Top; break;
        case Command::SideView: ui.request_view = ViewPreset::Side; break;
        case Command::ToggleHelp: ui.show_help = !ui.show_help; break;
    }
}

void shortcuts_window(Ui& ui) {
    if (!ui.show_help) return;
    // Centred below the menu bar every frame: placed once, before its first frame has measured its size,
    // it hung from the window's middle and ran past the bottom. Within the window (a short one scrolls).
    const float top = ui.menu_height, height = float(ui.window_size.y) - top;
    ImGui::SetNextWindowPos(ImVec2(0.5f * float(ui.window_size.x), top + 0.5f * height), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(float(ui.window_size.x), height));
    if (ImGui::Begin("Shortcuts", &ui.show_help, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove)) {
        if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
            for (const Shortcut& k : shortcuts()) {
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(k.keys);
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(k.what);
            }
            for (const Gesture& g : gestures()) {
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(g.input);
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(g.what);
            }
            ImGui::EndTable();
        }
        ImGui::TextDisabled("keys act when no panel has the keyboard");
    }
    ImGui::End();
}

}  // namespace mobb::viewer
