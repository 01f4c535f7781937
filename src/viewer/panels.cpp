// The viewer's panels drawn in order each frame, the list the View menu, the columns and the settings
// file share, which panels open by default, and the ImGui style. Each panel has a file of its own
// (panels.h lists them).
#include "panels.h"

#include <algorithm>

#include <imgui.h>

#include "crowd_view.h"
#include "layout.h"
#include "shortcuts.h"

namespace mobb::viewer {

void apply_style() {
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.FramePadding = ImVec2(4, 2);
    style.ItemSpacing = ImVec2(6, 3);
    style.WindowRounding = 0;  // panels stand flush in their columns
    style.Alpha = 0.96f;
}

const std::vector<PanelInfo>& panel_list() {
    using C = Column;
    // The lists' least heights (pixels): 150 holds the Trace panel's controls and two rows, or eight rows
    // of Recursion; 250 the Crowd panel's controls and its two lists of three rows (crowd_panel.cpp).
    static const std::vector<PanelInfo> list = {
        {"Scene", &PanelsOpen::scene, C::Left, false, 0},   {"Query", &PanelsOpen::query, C::Right, false, 0},
        {"Trace", &PanelsOpen::trace, C::Right, true, 150}, {"Recursion", &PanelsOpen::recursion, C::Left, true, 150},
        {"Tree fit", &PanelsOpen::fit, C::Left, false, 0},  {"Inspector", &PanelsOpen::inspector, C::Left, false, 0},
        {"Crowd", &PanelsOpen::crowd, C::Right, true, 250}, {"Timeline", &PanelsOpen::timeline, C::Bottom, false, 0},
        {"Open", &PanelsOpen::open, C::Floating, false, 0},
    };
    return list;
}

const PanelInfo& panel_info(bool PanelsOpen::*open) {
    const auto& list = panel_list();
    return *std::find_if(list.begin(), list.end(), [&](const PanelInfo& p) { return p.open == open; });
}

PanelsOpen default_panels(const State& s, const std::map<std::string, bool>& choices) {
    PanelsOpen p;
    if (s.crowd) {
        p.query = p.trace = p.recursion = s.crowd->opened_candidate >= 0;
        p.crowd = p.timeline = true;
    }
    for (const PanelInfo& info : panel_list())
        if (const auto c = choices.find(info.name); c != choices.end()) p.*info.open = c->second;
    return p;
}

void open_when_used(Ui& ui, bool PanelsOpen::*panel) {
    const auto choice = ui.panel_choices.find(panel_info(panel).name);
    if (choice == ui.panel_choices.end() || choice->second) ui.panels.*panel = true;
}

void choose_panel(Ui& ui, bool PanelsOpen::*panel, bool open) {
    ui.panels.*panel = open;
    ui.panel_choices[panel_info(panel).name] = open;
}

void draw_panels(State& s, Ui& ui) {
    open_dropped(s, ui);
    main_menu(s, ui);
    place_panels(s, ui);
    scene_panel(s, ui);
    query_panel(s, ui);
    trace_panel(s, ui);
    recursion_panel(s, ui);
    tree_fit_panel(s, ui);
    inspector_panel(s, ui);
    crowd_panel(s, ui);
    timeline_panel(s, ui);
    open_panel(s, ui);
    shortcuts_window(ui);
}

}  // namespace mobb::viewer
