// The recursion view (the trace as a tree of node pairs) and the Trace panel's outcome strip.
#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "layout.h"
#include "panels.h"

namespace mobb::viewer {

namespace {

/// Subtrees with fewer events than this start folded.
constexpr int kTinySubtree = 8;

ImU32 outcome_u32(TraceOutcome o, float alpha = 1.0f) {
    const glm::vec3 c = render::outcome_color(o);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha));
}

const Recursion& recursion(const State& s, Ui& ui) {
    if (ui.recursion_revision != s.revision || ui.recursion.pair_of.size() != s.trace.size()) {
        const int a = s.scene.query_a, b = s.scene.query_b;
        ui.recursion = s.queried ? recursion_of(s.trace, *s.clips[std::size_t(a)].tree, *s.clips[std::size_t(b)].tree)
                                 : Recursion{};
        ui.recursion_revision = s.revision;
    }
    return ui.recursion;
}

struct RowContext {
    State& s;
    Ui& ui;
    const Recursion& r;
    int step_pair;
    std::vector<char> on_path;  ///< pairs from the root to the shown step's pair
    std::vector<char> held;     ///< pairs with an event whose node holds the picked disk
};

void pair_row(RowContext& c, int k) {
    const NodePair& p = c.r.pairs[std::size_t(k)];
    const TraceEvent& last = c.s.trace[std::size_t(p.end - 1)];
    char label[160];
    std::snprintf(label, sizeof label, "A%d x B%d %s%s (%d)##%d", int(p.node_a), int(p.node_b), to_string(p.outcome),
                  c.held[std::size_t(k)] ? " *" : "", p.events, k);
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
    if (p.children.empty()) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    if (k == c.step_pair) flags |= ImGuiTreeNodeFlags_Selected;
    if (c.ui.reveal_step && c.on_path[std::size_t(k)] && k != c.step_pair)
        ImGui::SetNextItemOpen(true, ImGuiCond_Always);
    else
        ImGui::SetNextItemOpen(p.events >= kTinySubtree || p.hit, ImGuiCond_Once);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::ColorConvertU32ToFloat4(outcome_u32(p.outcome)));
    const bool open = ImGui::TreeNodeEx(label, flags);
    ImGui::PopStyleColor();
    if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) go_to_step(c.s, c.ui, p.end - 1);
    if (k == c.step_pair && c.ui.reveal_step) ImGui::SetScrollHereY(0.5f);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("events %d..%d (last: %s test), %d with those below; click: select its last step", p.first,
                          p.end - 1, to_string(last.test), p.events);
    if (!open || p.children.empty()) return;
    for (int child : p.children) pair_row(c, child);
    ImGui::TreePop();
}

}  // namespace

void recursion_panel(State& s, Ui& ui) {
    if (!begin_panel(s, ui, &PanelsOpen::recursion)) return;
    const Recursion& r = recursion(s, ui);
    if (r.pairs.empty()) {
        ImGui::TextDisabled("no query trace");
        return ImGui::End();
    }
    ImGui::TextDisabled("%zu node pairs, %zu events", r.pairs.size(), s.trace.size());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("* marks pairs holding the picked disk");
    RowContext c{s, ui, r, -1, std::vector<char>(r.pairs.size(), 0), std::vector<char>(r.pairs.size(), 0)};
    const int step = shown_step(s);
    if (step >= 0) {
        c.step_pair = r.pair_of[std::size_t(step)];
        for (int k = c.step_pair; k >= 0; k = r.pairs[std::size_t(k)].parent) c.on_path[std::size_t(k)] = 1;
    }
    for (int e : ui.picked_events)
        if (e >= 0 && e < int(r.pair_of.size())) c.held[std::size_t(r.pair_of[std::size_t(e)])] = 1;
    ImGui::BeginChild("pairs", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::PushStyleVar(ImGuiStyleVar_IndentSpacing, 10.0f);  // deep recursions stay in view
    for (int k = 0; k < int(r.pairs.size()); ++k)
        if (r.pairs[std::size_t(k)].parent < 0) pair_row(c, k);
    ImGui::PopStyleVar();
    ImGui::EndChild();
    ui.reveal_step = false;
    ImGui::End();
}

void outcome_strip(State& s, Ui& ui) {
    const int n = int(s.trace.size());
    if (n == 0) return;
    const float w = std::max(ImGui::GetContentRegionAvail().x, 50.0f), h = 14.0f;
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("outcomes", ImVec2(w, h));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), IM_COL32(30, 30, 36, 255));
    auto x_of = [&](int e) { return p0.x + (float(e) + 0.5f) * w / float(n); };
    for (int e = 0; e < n; ++e) {
        const float x = x_of(e);
        draw->AddLine(ImVec2(x, p0.y + 3), ImVec2(x, p0.y + h), outcome_u32(s.trace[std::size_t(e)].outcome));
    }
    const int hit = recursion(s, ui).first_hit;
    if (hit >= 0) {  // the first hit: a red triangle above its tick
        const float x = x_of(hit);
        draw->AddTriangleFilled(ImVec2(x - 4, p0.y - 1), ImVec2(x + 4, p0.y - 1), ImVec2(x, p0.y + 5),
                                outcome_u32(TraceOutcome::Hit));
    }
    const int step = shown_step(s);
    if (step >= 0) draw->AddRect(ImVec2(x_of(step) - 2, p0.y), ImVec2(x_of(step) + 2, p0.y + h), IM_COL32_WHITE);
    if (!ImGui::IsItemHovered() && !ImGui::IsItemActive()) return;
    const int e = std::clamp(int((ImGui::GetIO().MousePos.x - p0.x) / w * float(n)), 0, n - 1);
    const TraceEvent& ev = s.trace[std::size_t(e)];
    ImGui::SetTooltip("step %d: A%d x B%d %s %s%s", e, int(ev.node_a), int(ev.node_b), to_string(ev.test),
                      to_string(ev.outcome), e == hit ? " (first hit)" : "");
    if (ImGui::IsItemActive() && e != step) go_to_step(s, ui, e);
}

void click_disk(State& s, Ui& ui, const Pick& p) {
    if (p.clip < 0) return;
    ui.ruler = ui.pick;
    ui.pick = p;
    ui.picked_events.clear();
    open_when_used(ui, &PanelsOpen::inspector);
    const int side = p.clip == s.scene.query_a ? 0 : p.clip == s.scene.query_b ? 1 : -1;
    if (!s.queried || side < 0) return;
    ui.picked_events = events_holding(s.trace, *s.clips[std::size_t(p.clip)].tree, side, p.sample);
    if (!ui.picked_events.empty()) go_to_step(s, ui, ui.picked_events.back());
}

void click_box(State& s, Ui& ui, int clip, std::int32_t node) {
    const int side = clip == s.scene.query_a ? 0 : clip == s.scene.query_b ? 1 : -1;
    if (side < 0) return;
    ui.picked_events = events_of_node(s.trace, side, node);
    if (!ui.picked_events.empty()) go_to_step(s, ui, ui.picked_events.back());
}

}  // namespace mobb::viewer
