// The main menu bar: File (open, save) and View (every panel, the columns, smooth edges, the Shortcuts
// window). Its
// height is kept in ui.menu_height so the panels open below it.
#include <imgui.h>

#include "layout.h"
#include "panels.h"

namespace mobb::viewer {

void main_menu(State& s, Ui& ui) {
    if (!ImGui::BeginMainMenuBar()) return;
    ui.menu_height = ImGui::GetWindowSize().y;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open...", "O")) choose_panel(ui, &PanelsOpen::open, true);
        if (ImGui::MenuItem("Save scene", nullptr, false, s.crowd == nullptr)) save_to_path(s, ui);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        // The crowd's panels only when a crowd is loaded: they have nothing to show otherwise.
        for (const PanelInfo& p : panel_list())
            if (!crowd_only(p) || s.crowd)
                if (bool open = ui.panels.*p.open; ImGui::MenuItem(p.name, nullptr, &open))
                    choose_panel(ui, p.open, open);
        ImGui::Separator();
        if (ImGui::MenuItem("Left column", "[", !ui.columns.left_collapsed)) toggle_column(ui, Column::Left);
        if (ImGui::MenuItem("Right column", "]", !ui.columns.right_collapsed)) toggle_column(ui, Column::Right);
        if (ImGui::MenuItem("Bottom strip", nullptr, !ui.columns.bottom_collapsed)) toggle_column(ui, Column::Bottom);
        if (ImGui::MenuItem("All columns", "Tab")) toggle_columns(ui);
        ImGui::Separator();
        // One sample per pixel: under llvmpipe about 3x less fill work, at the price of jagged edges.
        ImGui::MenuItem("Smooth edges (MSAA)", nullptr, &s.scene.multisample);
        ImGui::MenuItem("Shortcuts", "F1", &ui.show_help);
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

}  // namespace mobb::viewer
