// Small ImGui pieces several panels share: colours, the clip chooser and what the panels draw over their
// plots (where a panel stands is layout.h's). One home for each, so the panels agree.
#pragma once
#include <vector>

#include <imgui.h>
#include <glm/vec3.hpp>

#include "state.h"

namespace mobb::viewer {

/// A crowd's events as the Crowd panel draws them (timeline strip, plots, counts): fallbacks orange,
/// contacts red. The 3D view's colours are render::clip_color and its kin.
inline const ImVec4 kFallbackColour(1.0f, 0.63f, 0.16f, 1.0f);
inline const ImVec4 kContactColour(0.92f, 0.16f, 0.16f, 1.0f);

/// An opaque ImGui colour from a render colour (render::clip_color, level_color, outcome_color).
inline ImVec4 imvec(const glm::vec3& c) { return {c.r, c.g, c.b, 1.0f}; }

/// A combo over the state's clips by name ("-" when `index` is none of them); true when one was chosen.
bool clip_combo(const char* label, int* index, const State& s);

/// A plot's horizontal position under the mouse, 0..1 over the last item.
float plot_fraction();
/// One more series drawn over the last PlotLines item, on its scale [lo, hi].
void plot_overlay(const std::vector<float>& values, float lo, float hi, ImU32 colour);
/// A vertical line at time t on the last plot item spanning [t0, t1] (the time cursor).
void time_line(double t, double t0, double t1, ImU32 colour);

}  // namespace mobb::viewer
