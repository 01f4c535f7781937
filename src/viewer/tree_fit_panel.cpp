// The Tree fit panel: how tightly MOBB, UMOBB and PCA-fitted boxes cover one clip, level by level (a
// table and a plot); clicking the plot shows that level's boxes.
#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "layout.h"
#include "panels.h"
#include "widgets.h"

namespace mobb::viewer {

namespace {

/// Rebuilds the three fits when the clip, n_min or the scene changed (each build is a whole tree).
void update_fit(const State& s, FitTable& fit) {
    if (fit.clip == -1 && !s.clips.empty()) fit.clip = std::max(0, s.scene.query_a);
    if (fit.clip < 0 || fit.clip >= int(s.clips.size())) return;
    if (fit.revision == s.revision && fit.n_min == s.scene.tree.n_min && !fit.mobb.empty()) return;
    const Path& path = s.clips[std::size_t(fit.clip)].tree->path();
    TreeOptions o;
    o.n_min = s.scene.tree.n_min;
    o.type = TreeType::Mobb;
    fit.mobb = level_stats(Tree::build(path, o));
    o.type = TreeType::Umobb;
    fit.umobb = level_stats(Tree::build(path, o));
    o.type = TreeType::Mobb;
    o.fit = AxisFit::Pca;
    fit.pca = level_stats(Tree::build(path, o));
    fit.n_min = s.scene.tree.n_min;
    fit.revision = s.revision;
}

void fit_row(const LevelStats& m, const LevelStats& u, const LevelStats& p) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextColored(imvec(render::level_color(m.level)), "%d", m.level);
    ImGui::TableNextColumn();
    ImGui::Text("%d", m.nodes);
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", m.mean_area);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", m.area_ratio);
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", u.mean_volume);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", u.volume_ratio);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", p.area_ratio);
}

/// One row per level, five in view (the rest scroll under the frozen header).
void fit_table(const FitTable& fit) {
    const ImGuiTableFlags flags =
        ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
    const float rows_shown = float(std::min<std::size_t>(fit.mobb.size(), 5)) + 1.3f;
    if (!ImGui::BeginTable("fit", 7, flags, ImVec2(0, rows_shown * ImGui::GetTextLineHeightWithSpacing() + 4))) return;
    for (const char* h : {"lvl", "nodes", "MOBB m2", "tight", "UMOBB m2s", "tight", "PCA tight"})
        ImGui::TableSetupColumn(h);
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableHeadersRow();
    const std::size_t rows = std::min({fit.mobb.size(), fit.umobb.size(), fit.pca.size()});
    for (std::size_t r = 0; r < rows; ++r) fit_row(fit.mobb[r], fit.umobb[r], fit.pca[r]);
    ImGui::EndTable();
}

/// Tightness per level (ImGui's PlotLines): MOBB area ratio (white), UMOBB volume ratio (blue), PCA
/// area ratio (orange); lower is tighter. Clicking a level shows its boxes.
void tightness_plot(State& s, const FitTable& fit) {
    const std::size_t rows = std::min({fit.mobb.size(), fit.umobb.size(), fit.pca.size()});
    if (rows < 2) return;
    std::vector<float> m, u, p;
    float high = 1.0f;
    for (std::size_t r = 0; r < rows; ++r) {
        m.push_back(float(fit.mobb[r].area_ratio));
        u.push_back(float(fit.umobb[r].volume_ratio));
        p.push_back(float(fit.pca[r].area_ratio));
        high = std::max({high, m.back(), u.back(), p.back()});
    }
    ImGui::TextColored(ImVec4(0.85f, 0.85f, 0.85f, 1), "MOBB");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.4f, 0.6f, 1.0f, 1), "UMOBB");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1), "PCA");
    ImGui::SameLine();
    ImGui::TextDisabled("by level, 1 = perfect (bottom)");
    ImGui::PushStyleColor(ImGuiCol_PlotLines, ImVec4(0.85f, 0.85f, 0.85f, 1));
    ImGui::PlotLines("##tightness", m.data(), int(m.size()), 0, nullptr, 1.0f, high * 1.05f,
                     ImVec2(ImGui::GetContentRegionAvail().x, 48));
    ImGui::PopStyleColor();
    plot_overlay(u, 1.0f, high * 1.05f, IM_COL32(100, 150, 255, 255));
    plot_overlay(p, 1.0f, high * 1.05f, IM_COL32(255, 150, 50, 255));
    if (ImGui::IsItemClicked())
        s.scene.layers.level = std::min(int(rows) - 1, int(std::lround(plot_fraction() * float(rows - 1))));
}

}  // namespace

void tree_fit_panel(State& s, Ui& ui) {
    if (!begin_panel(s, ui, &PanelsOpen::fit, ImGuiWindowFlags_HorizontalScrollbar)) return;
    if (clip_combo("clip", &ui.fit.clip, s)) ui.fit.mobb.clear();
    update_fit(s, ui.fit);
    ImGui::TextDisabled("tight = box / covered (area, volume); 1 is perfect");
    fit_table(ui.fit);
    tightness_plot(s, ui.fit);
    ImGui::End();
}

}  // namespace mobb::viewer
