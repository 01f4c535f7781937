// The inspector: the disk clicked last and the one before it, with a ruler between them (distance,
// time gap, r_a + r_b), both ringed in the 3D view. Picks name a clip and a sample, so they survive
// scrubbing, trace steps and reruns of the query.
#include <cstdio>

#include <imgui.h>
#include <glm/mat4x4.hpp>

#include "layout.h"
#include "panels.h"
#include "picking.h"
#include "space.h"
#include "widgets.h"

namespace mobb::viewer {

namespace {

/// Where a space-time point lands on the screen, or nothing behind the camera.
bool project(const State& s, const Ui& ui, const glm::dvec2& xy, double t, ImVec2& out) {
    const float w = float(ui.window_size.x), h = float(std::max(ui.window_size.y, 1));
    const glm::vec4 p = s.camera.projection(w / h) * s.camera.view() *
                        glm::vec4(render::to_gl(xy.x, xy.y, t, s.scene.time_scale), 1.0f);
    if (p.w <= 1e-6f) return false;
    out = ImVec2((p.x / p.w * 0.5f + 0.5f) * w, (0.5f - p.y / p.w * 0.5f) * h);
    return true;
}

void disk_lines(const State& s, const char* role, const Pick& p) {
    const auto d = disk_of(s, p);
    if (!d) return;
    ImGui::TextColored(imvec(render::clip_color(p.clip)), "%s: clip %d (%s), sample %d", role, p.clip,
                       s.clips[std::size_t(p.clip)].name.c_str(), p.sample);
    // Two short lines rather than one long one: they fit the right column's width.
    ImGui::Text("  t %.3f .. %.3f s, r %.3f m", d->t0, d->t1, d->r);
    ImGui::Text("  at %.3f, %.3f m", d->centre.x, d->centre.y);
}

/// Rings the picked disks at their sample's mid-time and joins them with the ruler's line.
void overlay(const State& s, const Ui& ui) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    ImVec2 at[2];
    bool shown[2] = {false, false};
    const Pick* picks[2] = {&ui.pick, &ui.ruler};
    for (int k = 0; k < 2; ++k) {
        const auto d = disk_of(s, *picks[k]);
        if (!d || !project(s, ui, d->centre, 0.5 * (d->t0 + d->t1), at[k])) continue;
        shown[k] = true;
        draw->AddCircle(at[k], 7.0f, k == 0 ? IM_COL32(255, 255, 255, 255) : IM_COL32(255, 220, 80, 255), 0, 2.0f);
    }
    if (shown[0] && shown[1]) draw->AddLine(at[0], at[1], IM_COL32(255, 220, 80, 230), 2.0f);
}

}  // namespace

void inspector_panel(State& s, Ui& ui) {
    overlay(s, ui);
    if (!begin_panel(s, ui, &PanelsOpen::inspector)) return;
    if (!disk_of(s, ui.pick)) {
        ImGui::TextDisabled("click a disk; click another to measure");
        return ImGui::End();
    }
    disk_lines(s, "picked", ui.pick);
    if (const auto r = measure(s, ui.ruler, ui.pick)) {
        disk_lines(s, "from", ui.ruler);
        ImGui::Separator();
        ImGui::Text("distance %.3f m   r_a + r_b %.3f m", r->distance, r->radii);
        ImGui::TextColored(r->clearance < 0 ? ImVec4(0.95f, 0.3f, 0.3f, 1) : ImVec4(0.4f, 0.85f, 0.45f, 1),
                           "clearance %.3f m (%s)", r->clearance, r->clearance < 0 ? "overlap in space" : "apart");
        ImGui::Text("time gap %.3f s%s", r->time_gap, r->time_gap == 0 ? " (their times overlap)" : "");
    }
    if (ImGui::SmallButton("clear (Esc)")) ui.pick = ui.ruler = {}, ui.picked_events.clear();
    ImGui::End();
}

}  // namespace mobb::viewer
