// The window's layout: panels stand in a left and a right column and a crowd's timeline in a strip at
// the bottom between them (Dear ImGui 1.86 has no docking, so each frame places them at fixed positions
// and sizes); the 3D view gets the free rectangle between the columns, below the menu bar and above the
// strip, its viewport: the camera's aspect, picking, framing and
// the axis labels use it, so nothing of the scene lies under a panel.
#pragma once
#include "panels.h"
#include "renderer.h"
#include "state.h"

namespace mobb::viewer {

/// Whether the panel is drawn only when a crowd is loaded (Crowd, Timeline).
bool crowd_only(const PanelInfo& panel);
/// Whether the panel is drawn this frame: open and, for a crowd's panel, a crowd loaded.
bool panel_shown(const State& state, const Ui& ui, const PanelInfo& panel);

/// The column a panel stands in this frame: its own (PanelInfo::column), or for a list the other one
/// when place_panels moved it there to balance the columns' heights (Ui::moved).
Column placed_column(const Ui& ui, const PanelInfo& panel);

/// The width a column takes this frame: 0 when collapsed or none of its panels is shown.
float column_width(const State& state, const Ui& ui, Column column);

/// The height the bottom strip takes this frame, between the columns: 0 when collapsed or none of its
/// panels is shown; else as tall as its panel's content, within kMaxStrip of the window.
float strip_height(const State& state, const Ui& ui);

/// The 3D view's viewport: the window between the columns, below the menu bar, above the bottom strip.
Rect viewport(const State& state, const Ui& ui);

/// A window rectangle in GL framebuffer pixels (origin bottom-left; a HiDPI framebuffer has more pixels
/// than the window).
render::Viewport gl_viewport(const Rect& rect, const glm::ivec2& window, const glm::ivec2& framebuffer);

/// Places this frame's column panels in ui.panel_rects (after the menu bar, before the panels). A list
/// (Trace, Recursion, Crowd) stands in the other column when that lowers the taller column's content by
/// two rows or more, so that both columns fit the window without scrolling where they can.
void place_panels(const State& state, Ui& ui);

/// ImGui::Begin for a panel at its place: in its column at the size the layout gave it (a width the user
/// drags becomes the column's), or floating from the viewport's top-left corner. False when nothing is
/// to be drawn (closed, in a collapsed column, folded); else end it with ImGui::End. (An int for the
/// flags keeps ImGui out of this header: the tests include it.)
bool begin_panel(State& state, Ui& ui, bool PanelsOpen::*panel, int flags = 0);  // flags: ImGuiWindowFlags

/// Collapses or expands a column or the bottom strip (the [ and ] keys, the View menu).
void toggle_column(Ui& ui, Column column);
/// Collapses both columns and the bottom strip, or expands them all when all are collapsed (Tab): the 3D
/// view alone.
void toggle_columns(Ui& ui);

/// Carries out the camera requests of this frame (presets, frame all) for the viewport's aspect.
void apply_requests(State& state, Ui& ui);

}  // namespace mobb::viewer
