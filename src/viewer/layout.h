// The window's layout: panels stand in a left and a right column (Dear ImGui 1.86 has no docking, so
// each frame places them at fixed positions and sizes) and the 3D view gets the free rectangle
// between the columns and below the menu bar, its viewport: the camera's aspect, picking, framing and
// the axis labels use it, so nothing of the scene lies under a panel.
#pragma once
#include "panels.h"
#include "renderer.h"
#include "state.h"

namespace mobb::viewer {

/// Whether the panel is drawn this frame: open and, for the Crowd panel, a crowd loaded.
bool panel_shown(const State& state, const Ui& ui, const PanelInfo& panel);

/// The width a column takes this frame: 0 when collapsed or none of its panels is shown.
float column_width(const State& state, const Ui& ui, Column column);

/// The 3D view's viewport: the window between the columns, below the menu bar.
Rect viewport(const State& state, const Ui& ui);

/// A window rectangle in GL framebuffer pixels (origin bottom-left; a HiDPI framebuffer has more pixels
/// than the window).
render::Viewport gl_viewport(const Rect& rect, const glm::ivec2& window, const glm::ivec2& framebuffer);

/// Places this frame's column panels in ui.panel_rects (after the menu bar, before the panels).
void place_panels(const State& state, Ui& ui);

/// ImGui::Begin for a panel at its place: in its column at the size the layout gave it (a width the user
/// drags becomes the column's), or floating from the viewport's top-left corner. False when nothing is
/// to be drawn (closed, in a collapsed column, folded); else end it with ImGui::End. (An int for the
/// flags keeps ImGui out of this header: the tests include it.)
bool begin_panel(State& state, Ui& ui, bool PanelsOpen::*panel, int flags = 0);  // flags: ImGuiWindowFlags

/// Collapses or expands a column (the [ and ] keys, the View menu).
void toggle_column(Ui& ui, Column column);
/// Collapses both columns, or expands both when both are collapsed (Tab): the 3D view alone.
void toggle_columns(Ui& ui);

/// Carries out the camera requests of this frame (presets, frame all) for the viewport's aspect.
void apply_requests(State& state, Ui& ui);

}  // namespace mobb::viewer
