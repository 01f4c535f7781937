// The Timeline strip, for a recorded crowd: the record in one line, play and the time cursor, where
// fallbacks and contacts fall along the run (a click jumps to one), and their counts per second. It
// stands in the bottom strip under the 3D view (layout.h), as wide as the view.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <imgui.h>

#include "crowd_view.h"
#include "layout.h"
#include "panels.h"
#include "widgets.h"

namespace mobb::viewer {

namespace {

/// The run as a strip: fallbacks (upper half) and frames with contacts (lower half) at their time, the
/// cursor in white. Hover names the nearest mark; a click jumps to it (or to the time clicked),
/// dragging scrubs.
void timeline_strip(State& s, Ui& ui) {
    CrowdView& v = *s.crowd;
    const crowd::Record& r = v.record();
    const float w = std::max(ImGui::GetContentRegionAvail().x, 50.0f), h = 18.0f;
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("timeline", ImVec2(w, h));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), IM_COL32(38, 38, 44, 255));
    const double frames = double(std::max<std::int64_t>(1, r.frames));
    auto x_of = [&](double f) { return p0.x + w * float(f / frames); };
    const ImU32 fallback_colour = ImGui::ColorConvertFloat4ToU32(kFallbackColour);
    const ImU32 contact_colour = ImGui::ColorConvertFloat4ToU32(kContactColour);
    for (const TimelineMark& m : v.marks) {
        const float x = x_of(double(m.frame));
        const bool fallback = m.kind == TimelineMark::Fallback;
        draw->AddLine(ImVec2(x, fallback ? p0.y : p0.y + h / 2), ImVec2(x, fallback ? p0.y + h / 2 : p0.y + h),
                      fallback ? fallback_colour : contact_colour);
    }
    const float cx = x_of(s.scene.cursor / r.dt);
    draw->AddLine(ImVec2(cx, p0.y), ImVec2(cx, p0.y + h), IM_COL32(255, 255, 255, 255), 2.0f);
    if (!ImGui::IsItemHovered() && !ImGui::IsItemActive()) return;
    const auto frame = std::int64_t((ImGui::GetIO().MousePos.x - p0.x) / w * float(frames));
    const TimelineMark* near = nearest_mark(v.marks, frame, std::int64_t(4.0 / w * frames) + 1);
    if (near && near->kind == TimelineMark::Fallback)
        ImGui::SetTooltip("fallback: agent %d at %.2f s", near->agent, double(near->frame) * r.dt);
    else if (near)
        ImGui::SetTooltip("%d agent pairs in contact at %.2f s", near->count, double(near->frame) * r.dt);
    if (ImGui::IsItemClicked() && near) {
        try {
            jump_to(s, *near);
        } catch (const std::runtime_error& e) {  // the choice point cannot be read
            ui.status = e.what();
        }
    } else if (ImGui::IsItemActive())
        s.scene.cursor = std::clamp(double(frame), 0.0, frames) * r.dt;
}

/// Fallbacks and agent pairs in contact per second of the run (ImGui's PlotHistogram); a click moves the
/// time cursor there.
void events_over_time(State& s) {
    if (s.crowd->marks.empty()) return;  // nothing to plot: the counts below say so
    const crowd::Record& r = s.crowd->record();
    const double seconds = double(r.frames) * r.dt;
    const int bins = std::clamp(int(std::ceil(seconds)), 1, 600);
    std::vector<float> fallbacks(std::size_t(bins), 0.0f), contacts(std::size_t(bins), 0.0f);
    for (const TimelineMark& m : s.crowd->marks) {
        const auto b = std::size_t(std::clamp(int(double(m.frame) * r.dt / seconds * bins), 0, bins - 1));
        if (m.kind == TimelineMark::Fallback)
            fallbacks[b] += 1.0f;
        else
            contacts[b] += float(m.count);
    }
    // Side by side, half the strip each.
    const float w = std::floor((ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) / 2);
    const auto plot = [&](const char* id, const std::vector<float>& v, ImVec4 colour, const char* what) {
        const float high = std::max(1.0f, *std::max_element(v.begin(), v.end()));
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "%s per second (max %.0f)", what, double(high));
        ImGui::PushStyleColor(ImGuiCol_PlotHistogram, colour);
        ImGui::PlotHistogram(id, v.data(), int(v.size()), 0, overlay, 0.0f, high, ImVec2(w, 30));
        ImGui::PopStyleColor();
        time_line(s.scene.cursor, 0.0, seconds, IM_COL32(255, 255, 255, 200));
        if (ImGui::IsItemClicked()) s.scene.cursor = double(plot_fraction()) * seconds;
    };
    plot("##fallbacks", fallbacks, kFallbackColour, "fallbacks");
    ImGui::SameLine();
    plot("##contacts", contacts, kContactColour, "contact pairs");
}

/// The record in one line, then play, rate and the time slider.
void playback(State& s) {
    CrowdView& v = *s.crowd;
    const crowd::Record& r = v.record();
    const std::string scenario = r.scenario.empty() ? "" : "scenario " + r.scenario + ", ";
    ImGui::Text("%s%d agents, %.1f s, %s, seed %llu", scenario.c_str(), v.agents, double(r.frames) * r.dt,
                r.select.c_str(), static_cast<unsigned long long>(r.seed));
    if (ImGui::Button(v.playing ? "pause" : "play")) v.playing = !v.playing;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::SliderFloat("rate", &v.rate, 0.1f, 4.0f, "%.1f x");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(120.0f, ImGui::GetContentRegionAvail().x - 60.0f));  // room for its label
    float t = float(s.scene.cursor);
    if (ImGui::SliderFloat("time", &t, 0.0f, float(double(r.frames) * r.dt), "%.2f s")) s.scene.cursor = double(t);
}

/// How many fallbacks and frames with contacts the run has (of a record read in windows: the frames
/// read so far, and the frames at hand).
void event_counts(const CrowdView& v) {
    const auto count = [&](TimelineMark::Kind kind) {
        return std::count_if(v.marks.begin(), v.marks.end(), [&](const auto& m) { return m.kind == kind; });
    };
    ImGui::TextColored(kFallbackColour, "%ld fallbacks", long(count(TimelineMark::Fallback)));
    ImGui::SameLine();
    ImGui::TextColored(kContactColour, "%ld contact frames%s", long(count(TimelineMark::Contact)),
                       v.whole() ? "" : " in the frames read");
    if (v.whole()) return;
    const crowd::Record& r = v.record();
    ImGui::SameLine();
    ImGui::TextDisabled("frames at hand: %.1f to %.1f s", double(v.window.first) * r.dt, double(v.window.last) * r.dt);
}

}  // namespace

void timeline_panel(State& s, Ui& ui) {
    if (!begin_panel(s, ui, &PanelsOpen::timeline)) return;
    playback(s);
    timeline_strip(s, ui);
    events_over_time(s);
    event_counts(*s.crowd);
    ImGui::End();
}

}  // namespace mobb::viewer
