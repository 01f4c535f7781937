// The Query panel: choose clips A and B and place them, the tree type and n_min, run the query, and
// read its answer, its test counts and the distance between the two clips over time.
#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "layout.h"
#include "mobb/core/angle.h"
#include "panels.h"
#include "scene.h"
#include "widgets.h"

namespace mobb::viewer {

namespace {

bool placement_fields(const char* id, Placement& p) {
    ImGui::PushID(id);
    double xy[2] = {p.x, p.y}, turn[2] = {degrees(p.theta), p.t0};
    const double lo = -kFar, hi = kFar;  // a scene file's range
    bool changed = false;
    if (ImGui::DragScalarN("x y (m)", ImGuiDataType_Double, xy, 2, 0.01f, &lo, &hi, "%.2f")) {
        p.x = xy[0], p.y = xy[1];
        changed = true;
    }
    if (ImGui::DragScalarN("deg t0 (s)", ImGuiDataType_Double, turn, 2, 0.05f, &lo, &hi, "%.2f")) {
        p.theta = radians(turn[0]), p.t0 = turn[1];
        changed = true;
    }
    ImGui::PopID();
    return changed;
}

/// Clip `k` (A or B) by name in its colour, with its placement; true when the placement changed.
bool query_clip(State& s, const char* role, const char* id, int k) {
    if (k < 0 || k >= int(s.clips.size())) return false;
    ImGui::TextColored(imvec(render::clip_color(k)), "%s: %s", role, s.clips[std::size_t(k)].name.c_str());
    return placement_fields(id, s.places[std::size_t(k)]);
}

// The distance between the query's clips A and B over time (ImGui's PlotLines, metres) against
// r_a + r_b (red): where the distance dips under the red line the disks overlap. Clicking moves the
// time cursor there.
void distance_plot(State& s) {
    if (s.clearance.empty()) return ImGui::TextDisabled("the clips never meet in time");
    const Path& pa = s.clips[std::size_t(s.scene.query_a)].tree->path();
    const Path& pb = s.clips[std::size_t(s.scene.query_b)].tree->path();
    std::vector<float> distance, radii;
    float high = 0;
    std::size_t least = 0;
    for (std::size_t k = 0; k < s.clearance.size(); ++k) {
        const ClearanceSample& c = s.clearance[k];
        const double r = pa.samples[std::size_t(c.i)].r + pb.samples[std::size_t(c.j)].r;
        distance.push_back(float(c.gap + r));
        radii.push_back(float(r));
        high = std::max({high, distance.back(), radii.back()});
        if (c.gap < s.clearance[least].gap) least = k;
    }
    high *= 1.05f;
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "closest %.2f m at %.2f s", double(distance[least]), s.clearance[least].t);
    ImGui::TextUnformatted("distance A-B against r_a + r_b (red), m");
    ImGui::PlotLines("##distance", distance.data(), int(distance.size()), 0, overlay, 0.0f, high,
                     ImVec2(ImGui::GetContentRegionAvail().x, 64));
    plot_overlay(radii, 0.0f, high, IM_COL32(230, 60, 60, 220));
    time_line(s.scene.cursor, s.clearance.front().t, s.clearance.back().t, IM_COL32(240, 200, 80, 220));
    if (ImGui::IsItemClicked())
        s.scene.cursor =
            s.clearance[std::min(s.clearance.size() - 1, std::size_t(plot_fraction() * float(s.clearance.size())))].t;
}

/// The tree type and n_min; a change rebuilds every tree (which reruns the query). True when rebuilt.
bool tree_options(State& s) {
    const auto type_label = [](void*, int k, const char** out) {
        *out = kTreeTypes[k].label;
        return true;
    };
    int type = int(s.scene.tree.type);
    bool rebuild = ImGui::Combo("tree", &type, type_label, nullptr, kTreeTypeCount);
    rebuild |= ImGui::SliderInt("n_min", &s.scene.tree.n_min, 1, 64);
    if (!rebuild) return false;
    s.scene.tree.type = TreeType(type);
    s.scene.tree.n_min = std::max(1, s.scene.tree.n_min);
    rebuild_trees(s);
    return true;
}

void answer(State& s) {
    if (!s.queried) return ImGui::TextDisabled("choose two different clips");
    ImGui::TextColored(s.answer ? ImVec4(0.9f, 0.1f, 0.1f, 1) : ImVec4(0.1f, 0.6f, 0.2f, 1), "%s",
                       s.answer ? "collide: yes" : "collide: no");
    if (s.answer) ImGui::Text("hit: A sample %lld, B sample %lld", (long long)s.hit.a, (long long)s.hit.b);
    ImGui::Text("2D tests %llu  3D tests %llu", (unsigned long long)s.stats.tests2d,
                (unsigned long long)s.stats.tests3d);
    ImGui::Text("sample tests %llu  events %zu", (unsigned long long)s.stats.samples, s.trace.size());
    distance_plot(s);
}

}  // namespace

void query_panel(State& s, Ui& ui) {
    if (!begin_panel(s, ui, &PanelsOpen::query)) return;
    bool rerun = clip_combo("A", &s.scene.query_a, s);
    rerun |= clip_combo("B", &s.scene.query_b, s);
    rerun |= query_clip(s, "A", "pa", s.scene.query_a);
    rerun |= query_clip(s, "B", "pb", s.scene.query_b);
    // The button is drawn only when nothing else asked for a run (ImGui's || short-circuits).
    if (!tree_options(s) && (rerun || ImGui::Button("run query"))) run_query(s);
    answer(s);
    ImGui::End();
}

}  // namespace mobb::viewer
