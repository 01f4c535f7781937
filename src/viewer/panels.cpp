// The viewer's panels drawn in order each frame, the list the View menu and the settings file share,
// and the ImGui style. Each panel has a file of its own (panels.h lists them).
#include "panels.h"

#include <imgui.h>

#include "shortcuts.h"

namespace mobb::viewer {

void apply_style() {
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.FramePadding = ImVec2(4, 2);
    style.ItemSpacing = ImVec2(6, 3);
    style.WindowRounding = 3;
    style.Alpha = 0.96f;
}

const std::vector<PanelInfo>& panel_list() {
    static const std::vector<PanelInfo> list = {
        {"Scene", &PanelsOpen::scene},         {"Query", &PanelsOpen::query},  {"Trace", &PanelsOpen::trace},
        {"Recursion", &PanelsOpen::recursion}, {"Tree fit", &PanelsOpen::fit}, {"Inspector", &PanelsOpen::inspector},
        {"Crowd", &PanelsOpen::crowd},         {"Open", &PanelsOpen::open},
    };
    return list;
}

void draw_panels(State& s, Ui& ui) {
    open_dropped(s, ui);
    main_menu(s, ui);
    scene_panel(s, ui);
    query_panel(s, ui);
    trace_panel(s, ui);
    recursion_panel(s, ui);
    tree_fit_panel(s, ui);
    inspector_panel(s, ui);
    crowd_panel(s, ui);
    open_panel(s, ui);
    shortcuts_window(ui);
}

}  // namespace mobb::viewer
