// The Trace panel: step through the query's trace events (buttons, slider, playback, the outcome strip)
// and list them; the time cursor moves to the shown step.
#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "crowd_view.h"
#include "layout.h"
#include "panels.h"
#include "widgets.h"

namespace mobb::viewer {

namespace {

void step_buttons(State& s, Ui& ui, int step, int last) {
    if (ImGui::Button("|<")) go_to_step(s, ui, 0);
    ImGui::SameLine();
    if (ImGui::Button("<")) go_to_step(s, ui, step - 1);
    ImGui::SameLine();
    if (ImGui::Button(ui.playing ? "pause" : "play")) ui.playing = !ui.playing;
    ImGui::SameLine();
    if (ImGui::Button(">")) go_to_step(s, ui, step + 1);
    ImGui::SameLine();
    if (ImGui::Button(">|")) go_to_step(s, ui, last);
}

/// Every event, one row each in its outcome's colour; the list clipper draws only the rows in view.
void event_list(State& s, Ui& ui, int step) {
    ImGui::BeginChild("events");
    ImGuiListClipper clipper;
    clipper.Begin(int(s.trace.size()));
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const TraceEvent& e = s.trace[std::size_t(i)];
            char line[128];
            std::snprintf(line, sizeof line, "%4d %-7s A%-4d B%-4d %s", i, to_string(e.test), int(e.node_a),
                          int(e.node_b), to_string(e.outcome));
            ImGui::PushStyleColor(ImGuiCol_Text, imvec(render::outcome_color(e.outcome) * 0.8f));
            if (ImGui::Selectable(line, i == step)) go_to_step(s, ui, i);
            ImGui::PopStyleColor();
        }
    }
    if (ui.scroll_to_step && step >= 0) {
        ImGui::SetScrollY(float(step) * ImGui::GetTextLineHeightWithSpacing() - ImGui::GetWindowHeight() * 0.5f);
        ui.scroll_to_step = false;
    }
    ImGui::EndChild();
}

}  // namespace

void trace_panel(State& s, Ui& ui) {
    if (!begin_panel(s, ui, &PanelsOpen::trace)) return;
    const int last = int(s.trace.size()) - 1;
    const int step = shown_step(s);
    step_buttons(s, ui, step, last);
    ImGui::SliderFloat("steps/s", &ui.rate, 0.5f, 60.0f, "%.1f");
    int k = step;
    if (last >= 0 && ImGui::SliderInt("step", &k, 0, last)) go_to_step(s, ui, k);
    outcome_strip(s, ui);
    ImGui::Checkbox("cursor at each step", &ui.cursor_at_step);
    ImGui::Separator();
    event_list(s, ui, step);
    ImGui::End();
}

void go_to_step(State& s, Ui& ui, int k) {
    if (s.trace.empty()) return;
    k = std::clamp(k, 0, int(s.trace.size()) - 1);
    s.scene.step = k;
    ui.scroll_to_step = true;
    ui.reveal_step = true;
    if (!ui.cursor_at_step) return;
    // The cursor goes to the middle of the time both nodes share (or node A's start when none).
    const TraceEvent& e = s.trace[std::size_t(k)];
    const int a = s.scene.query_a, b = s.scene.query_b;
    auto span = [&](int clip, std::int32_t node, double& t0, double& t1) {
        const Tree& tree = *s.clips[std::size_t(clip)].tree;
        if (node < 0 || node >= std::int32_t(tree.nodes().size())) return false;
        const Node& n = tree.nodes()[std::size_t(node)];
        t0 = sample_time(s.places[std::size_t(clip)], tree.path().dt, n.first);
        t1 = sample_time(s.places[std::size_t(clip)], tree.path().dt, n.end);
        return true;
    };
    double a0, a1, b0, b1;
    if (!span(a, e.node_a, a0, a1) || !span(b, e.node_b, b0, b1)) return;
    if (e.outcome == TraceOutcome::Hit && e.sample_a >= 0) {
        const Path& pa = s.clips[std::size_t(a)].tree->path();
        s.scene.cursor = sample_time(s.places[std::size_t(a)], pa.dt, e.sample_a) + 0.5 * pa.dt;
    } else {
        const double lo = std::max(a0, b0), hi = std::min(a1, b1);
        s.scene.cursor = lo < hi ? 0.5 * (lo + hi) : 0.5 * (a0 + a1);
    }
}

void update_playback(State& s, Ui& ui, double seconds) {
    update_crowd_playback(s, seconds);
    if (!ui.playing || s.trace.empty()) return;
    ui.play_clock += seconds * double(ui.rate);
    const int steps = int(ui.play_clock);
    if (steps <= 0) return;
    ui.play_clock -= steps;
    const int next = shown_step(s) + steps;
    if (next >= int(s.trace.size())) ui.playing = false;
    go_to_step(s, ui, next);
}

}  // namespace mobb::viewer
