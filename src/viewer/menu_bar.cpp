// The main menu bar: File (open, save) and View (every panel, the Shortcuts window). Its height is
// kept in ui.menu_height so the panels open below it.
#include <imgui.h>

#include "panels.h"

namespace mobb::viewer {

void main_menu(State& s, Ui& ui) {
    if (!ImGui::BeginMainMenuBar()) return;
    ui.menu_height = ImGui::GetWindowSize().y;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open...", "O")) ui.panels.open = true;
        if (ImGui::MenuItem("Save scene", nullptr, false, s.crowd == nullptr)) save_to_path(s, ui);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        // The Crowd panel only when a crowd is loaded: it has nothing to show otherwise.
        for (const PanelInfo& p : panel_list())
            if (p.open != &PanelsOpen::crowd || s.crowd) ImGui::MenuItem(p.name, nullptr, &(ui.panels.*p.open));
        ImGui::Separator();
        ImGui::MenuItem("Shortcuts", "F1", &ui.show_help);
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

}  // namespace mobb::viewer
