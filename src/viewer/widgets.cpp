#include "widgets.h"

#include <algorithm>

namespace mobb::viewer {

bool clip_combo(const char* label, int* index, const State& s) {
    const char* preview = *index >= 0 && *index < int(s.clips.size()) ? s.clips[std::size_t(*index)].name.c_str() : "-";
    bool changed = false;
    if (ImGui::BeginCombo(label, preview)) {
        for (int k = 0; k < int(s.clips.size()); ++k) {
            ImGui::PushID(k);
            if (ImGui::Selectable(s.clips[std::size_t(k)].name.c_str(), k == *index)) {
                *index = k;
                changed = true;
            }
            ImGui::PopID();
        }
        ImGui::EndCombo();
    }
    return changed;
}

float plot_fraction() {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    return std::clamp((ImGui::GetIO().MousePos.x - lo.x) / std::max(1.0f, hi.x - lo.x), 0.0f, 1.0f);
}

void plot_overlay(const std::vector<float>& values, float lo, float hi, ImU32 colour) {
    if (values.size() < 2 || !(hi > lo)) return;
    const ImGuiStyle& st = ImGui::GetStyle();
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    const float x0 = a.x + st.FramePadding.x, x1 = b.x - st.FramePadding.x;
    const float y0 = a.y + st.FramePadding.y, y1 = b.y - st.FramePadding.y;
    std::vector<ImVec2> line;
    for (std::size_t k = 0; k < values.size(); ++k)
        line.emplace_back(x0 + (x1 - x0) * float(k) / float(values.size() - 1),
                          y1 - (y1 - y0) * std::clamp((values[k] - lo) / (hi - lo), 0.0f, 1.0f));
    ImGui::GetWindowDrawList()->AddPolyline(line.data(), int(line.size()), colour, 0, 1.5f);
}

void time_line(double t, double t0, double t1, ImU32 colour) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    if (!(t1 > t0) || t < t0 || t > t1) return;
    const float x = lo.x + float((t - t0) / (t1 - t0)) * (hi.x - lo.x);
    ImGui::GetWindowDrawList()->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), colour);
}

}  // namespace mobb::viewer
