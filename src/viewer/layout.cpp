#include "layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <imgui.h>
#include <imgui_internal.h>

namespace mobb::viewer {

namespace {

constexpr float kMinColumn = 200.0f;
constexpr float kMaxStrip = 0.35f;     ///< the most of the window's height the bottom strip takes
constexpr float kMoveGain = 40.0f;     ///< pixels (two rows) a list's move must save the taller column
constexpr float kFirstStrip = 120.0f;  ///< the strip's height before its panel has measured its content

std::size_t index_of(const PanelInfo& info) { return std::size_t(&info - panel_list().data()); }

/// A column's width as the user left it, within what the window allows.
float clamped_width(float width, const Ui& ui) {
    return std::clamp(width, kMinColumn, std::max(kMinColumn, 0.4f * float(ui.window_size.x)));
}

/// How tall the panel's content made it last time it was drawn; infinite for panels that fill their
/// column and for those not drawn yet (their first frame takes a fair share, then they measure) or with
/// no ImGui context.
float wanted_height(const PanelInfo& info) {
    const ImGuiWindow* w = ImGui::GetCurrentContext() ? ImGui::FindWindowByName(info.name) : nullptr;
    if (info.fills || !w) return std::numeric_limits<float>::infinity();
    if (w->Collapsed) return w->TitleBarHeight();
    return w->TitleBarHeight() + 2.0f * w->WindowPadding.y + w->ContentSizeIdeal.y + w->ScrollbarSizes.y;
}

/// The height a panel needs in its column: its content's, or a list's least (PanelInfo::least).
float needed_height(const PanelInfo& info) { return info.fills ? info.least : wanted_height(info); }

/// The fitting case of share_height: the `least` heights, the spare height split among the lists; the
/// last panel takes what rounding (or the lack of lists) leaves over.
std::vector<float> share_fitting(const std::vector<float>& wanted, std::vector<float> out, float height) {
    float used = 0;
    for (float& h : out) used += h = std::floor(h);
    const auto lists = std::count_if(wanted.begin(), wanted.end(), [](float w) { return std::isinf(w); });
    const float each = lists > 0 ? std::floor((height - used) / float(lists)) : 0.0f;
    for (std::size_t k = 0; k < out.size(); ++k)
        if (std::isinf(wanted[k])) out[k] += each, used += each;
    if (!out.empty()) out.back() += height - used;
    return out;
}

/// Heights for a column: when the panels' content fits with each list's least height (`least`), each
/// panel is as tall as its content and the lists share the rest; else each panel is as tall as it wants
/// while that is within a fair share (water filling) and the others share the rest. The last takes any
/// left over.
std::vector<float> share_height(const std::vector<float>& wanted, const std::vector<float>& least, float height) {
    float content = 0;
    for (float h : least) content += h;
    if (content <= height) return share_fitting(wanted, least, height);
    std::vector<float> out(wanted.size(), -1.0f);
    float left = height;
    std::size_t unset = wanted.size();
    for (bool changed = true; changed && unset > 0;) {
        changed = false;
        const float share = left / float(unset);
        for (std::size_t k = 0; k < wanted.size(); ++k)
            if (out[k] < 0 && wanted[k] <= share) {
                out[k] = std::floor(wanted[k]);
                left -= out[k];
                --unset;
                changed = true;
            }
    }
    for (float& h : out)
        if (h < 0) {
            h = std::floor(left / float(unset--));
            left -= h;
        }
    if (!out.empty()) out.back() += left;
    return out;
}

void place_column(const State& s, Ui& ui, Column column) {
    const float width = column_width(s, ui, column);
    if (width <= 0) return;
    std::vector<const PanelInfo*> shown;
    std::vector<float> wanted, least;
    for (const PanelInfo& p : panel_list())
        if (placed_column(ui, p) == column && panel_shown(s, ui, p)) {
            shown.push_back(&p);
            wanted.push_back(wanted_height(p));
            least.push_back(needed_height(p));
        }
    const std::vector<float> heights = share_height(wanted, least, float(ui.window_size.y) - ui.menu_height);
    const float x = column == Column::Left ? 0.0f : float(ui.window_size.x) - width;
    float y = ui.menu_height;
    for (std::size_t k = 0; k < shown.size(); ++k) {
        ui.panel_rects[index_of(*shown[k])] = {x, y, width, heights[k]};
        y += heights[k];
    }
}

/// The height the panels standing in `column` need (needed_height), and how many they are; infinite
/// while one has not measured its content yet.
std::pair<float, int> column_need(const State& s, const Ui& ui, Column column) {
    float need = 0;
    int count = 0;
    for (const PanelInfo& p : panel_list())
        if (placed_column(ui, p) == column && panel_shown(s, ui, p)) need += needed_height(p), ++count;
    return {need, count};
}

/// Moves lists between the two columns, one at a time, while a move lowers the taller column's need by
/// more than kMoveGain (so that a move is not undone by a row's difference the next frame); a column is
/// never emptied, and nothing moves while either column is collapsed (the moved lists go home).
void balance_columns(const State& s, Ui& ui) {
    const auto& list = panel_list();
    ui.moved.resize(list.size(), false);
    const bool both = !ui.columns.left_collapsed && !ui.columns.right_collapsed;
    for (std::size_t k = 0; k < list.size(); ++k)
        if (!both || !panel_shown(s, ui, list[k])) ui.moved[k] = false;
    if (!both) return;
    for (std::size_t round = 0; round < list.size(); ++round) {
        const auto [left, lefts] = column_need(s, ui, Column::Left);
        const auto [right, rights] = column_need(s, ui, Column::Right);
        if (std::isinf(left) || std::isinf(right) || lefts == 0 || rights == 0) return;
        float best = std::max(left, right) - kMoveGain;
        std::size_t move = list.size();
        for (std::size_t k = 0; k < list.size(); ++k) {
            const PanelInfo& p = list[k];
            const Column at = placed_column(ui, p);
            if (!p.fills || !panel_shown(s, ui, p) || (at == Column::Left ? lefts : rights) == 1) continue;
            const float d = at == Column::Left ? p.least : -p.least;  // what the left column gives the right
            const float after = std::max(left - d, right + d);
            if (after < best) best = after, move = k;
        }
        if (move == list.size()) return;
        ui.moved[move] = !ui.moved[move];
    }
}

/// The panel standing in the bottom strip, if any is shown.
const PanelInfo* strip_panel(const State& s, const Ui& ui) {
    for (const PanelInfo& p : panel_list())
        if (p.column == Column::Bottom && panel_shown(s, ui, p)) return &p;
    return nullptr;
}

void place_strip(const State& s, Ui& ui) {
    const PanelInfo* panel = strip_panel(s, ui);
    const float height = strip_height(s, ui);
    if (!panel || height <= 0) return;
    const float left = column_width(s, ui, Column::Left), right = column_width(s, ui, Column::Right);
    ui.panel_rects[index_of(*panel)] = {left, float(ui.window_size.y) - height,
                                        std::max(1.0f, float(ui.window_size.x) - left - right), height};
}

}  // namespace

bool crowd_only(const PanelInfo& panel) {
    return panel.open == &PanelsOpen::crowd || panel.open == &PanelsOpen::timeline;
}

bool panel_shown(const State& s, const Ui& ui, const PanelInfo& panel) {
    return ui.panels.*panel.open && (!crowd_only(panel) || s.crowd);
}

float strip_height(const State& s, const Ui& ui) {
    const PanelInfo* panel = strip_panel(s, ui);
    if (!panel || ui.columns.bottom_collapsed) return 0;
    const float wanted = wanted_height(*panel);
    const float most = kMaxStrip * (float(ui.window_size.y) - ui.menu_height);
    return std::floor(std::min(std::isinf(wanted) ? kFirstStrip : wanted, most));
}

float column_width(const State& s, const Ui& ui, Column column) {
    if (column == Column::Floating || column == Column::Bottom) return 0;
    const bool left = column == Column::Left;
    if (left ? ui.columns.left_collapsed : ui.columns.right_collapsed) return 0;
    for (const PanelInfo& p : panel_list())
        if (placed_column(ui, p) == column && panel_shown(s, ui, p))
            return clamped_width(left ? ui.columns.left : ui.columns.right, ui);
    return 0;
}

Column placed_column(const Ui& ui, const PanelInfo& panel) {
    const std::size_t k = index_of(panel);
    if (k >= ui.moved.size() || !ui.moved[k]) return panel.column;
    return panel.column == Column::Left ? Column::Right : Column::Left;
}

Rect viewport(const State& s, const Ui& ui) {
    const float left = column_width(s, ui, Column::Left), right = column_width(s, ui, Column::Right);
    return {left, ui.menu_height, std::max(1.0f, float(ui.window_size.x) - left - right),
            std::max(1.0f, float(ui.window_size.y) - ui.menu_height - strip_height(s, ui))};
}

render::Viewport gl_viewport(const Rect& r, const glm::ivec2& window, const glm::ivec2& framebuffer) {
    const float sx = float(framebuffer.x) / float(std::max(window.x, 1));
    const float sy = float(framebuffer.y) / float(std::max(window.y, 1));
    const int x0 = int(std::lround(r.x * sx)), x1 = int(std::lround((r.x + r.width) * sx));
    const int y0 = int(std::lround((float(window.y) - r.y - r.height) * sy)),
              y1 = int(std::lround((float(window.y) - r.y) * sy));
    return {x0, y0, x1 - x0, y1 - y0};
}

void place_panels(const State& s, Ui& ui) {
    ui.panel_rects.assign(panel_list().size(), Rect{});
    balance_columns(s, ui);
    place_column(s, ui, Column::Left);
    place_column(s, ui, Column::Right);
    place_strip(s, ui);
}

bool begin_panel(State& s, Ui& ui, bool PanelsOpen::*panel, int flags) {
    const PanelInfo& info = panel_info(panel);
    if (!panel_shown(s, ui, info)) return false;
    bool& open = ui.panels.*panel;
    bool drawn = false;
    if (info.column == Column::Floating) {
        const Rect v = viewport(s, ui);
        ImGui::SetNextWindowPos(ImVec2(v.x + 8, v.y + 8), ImGuiCond_Appearing);
        drawn = ImGui::Begin(info.name, &open, flags);
    } else {
        const Rect r = ui.panel_rects[index_of(info)];
        if (r.width <= 0) return false;  // a collapsed column
        ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
        ImGui::SetNextWindowSize(ImVec2(r.width, r.height));
        // The strip follows the columns and its content: nothing of it to drag.
        const int fixed = info.column == Column::Bottom ? ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse : 0;
        drawn =
            ImGui::Begin(info.name, &open, flags | fixed | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
        // Dragging a panel's side edge resizes its whole column.
        const Column column = placed_column(ui, info);
        if (const float w = ImGui::GetWindowWidth(); column != Column::Bottom && std::abs(w - r.width) > 0.5f)
            (column == Column::Left ? ui.columns.left : ui.columns.right) = clamped_width(w, ui);
    }
    if (!open) choose_panel(ui, panel, false);  // its close button
    if (!drawn) ImGui::End();
    return drawn;
}

void toggle_column(Ui& ui, Column column) {
    Columns& c = ui.columns;
    bool& collapsed = column == Column::Left    ? c.left_collapsed
                      : column == Column::Right ? c.right_collapsed
                                                : c.bottom_collapsed;
    collapsed = !collapsed;
}

void toggle_columns(Ui& ui) {
    Columns& c = ui.columns;
    const bool collapse = !(c.left_collapsed && c.right_collapsed && c.bottom_collapsed);
    c.left_collapsed = c.right_collapsed = c.bottom_collapsed = collapse;
}

void apply_requests(State& s, Ui& ui) {
    if (ui.request_view == ViewPreset::Top) s.camera.top();
    if (ui.request_view == ViewPreset::Side) s.camera.side();
    if (ui.request_view != ViewPreset::None || ui.request_frame_all) frame_all(s, viewport(s, ui).aspect());
    ui.request_view = ViewPreset::None;
    ui.request_frame_all = false;
}

}  // namespace mobb::viewer
