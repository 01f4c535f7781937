// Dear ImGui panels, one .cpp each: scene and layers, query debugger, trace list, recursion view, tree
// fit, inspector, crowd, the crowd's timeline, open files; the main menu's View menu opens and closes each of them.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "mobb/core/tree.h"
#include "recursion.h"
#include "state.h"

namespace mobb::viewer {

/// A disk chosen by clicking in the 3D view.
struct Pick {
    int clip = -1;
    int sample = -1;
};

/// Which panels are open (each closable; the View menu lists them). What a scene opens by default;
/// default_panels() says what each kind of file opens.
struct PanelsOpen {
    bool scene = true, query = true, trace = true, recursion = true, fit = false, inspector = false, crowd = false;
    bool timeline = false;  ///< a crowd's playback and timeline, in the bottom strip
    bool open = false;      ///< the Open panel (data folder)
};

/// Where a panel stands: in the left or right column beside the 3D view, in the bottom strip under it
/// (between the columns), or floating over it.
enum class Column : std::uint8_t { Left, Right, Bottom, Floating };

struct PanelInfo {
    const char* name;  ///< the window title, also the key in the settings file
    bool PanelsOpen::*open;
    Column column;  ///< its own column; a list may stand in the other one to balance them (layout.h)
    bool fills;     ///< takes what its column has left (a list); the others are as tall as their content
    float least;    ///< a list's least height (pixels) before the other panels of its column give way
};
/// Every panel in View-menu order, which is also the top-down order within a column.
const std::vector<PanelInfo>& panel_list();
const PanelInfo& panel_info(bool PanelsOpen::*open);

/// The two columns of panels and the bottom strip: widths in pixels (dragging a panel's edge sets them),
/// and whether each is collapsed (its panels hidden, the 3D view takes the room). The settings file
/// keeps them.
struct Columns {
    float left = 315, right = 330;  // left: the Trace panel's rows fit when it stands there
    bool left_collapsed = false, right_collapsed = false, bottom_collapsed = false;
};

/// A rectangle in window pixels, origin top-left.
struct Rect {
    float x = 0, y = 0, width = 0, height = 0;
    float aspect() const { return width / (height > 1 ? height : 1); }
    bool contains(float px, float py) const { return px >= x && px < x + width && py >= y && py < y + height; }
};

/// The two camera presets, one name each across the code, the panels and the CLI: Top (the Scene and
/// Crowd panels' "top", the T key, `mobb render --crowd --top`) and Side (their "side", the S key). The
/// window applies a request, then frames everything.
enum class ViewPreset : std::uint8_t { None, Top, Side };

/// Per-level statistics of the three fits of one clip, for the tree-fit panel.
struct FitTable {
    int clip = -1;
    int n_min = 0;
    std::uint64_t revision = 0;
    std::vector<LevelStats> mobb, umobb, pca;
};

/// What the panels remember between frames (not part of a scene).
struct Ui {
    glm::ivec2 window_size{960, 540};
    bool playing = false;
    float rate = 8.0f;  ///< trace steps per second while playing
    double play_clock = 0.0;
    bool cursor_at_step = true;  ///< move the time cursor to each trace step
    bool scroll_to_step = true;
    PanelsOpen panels;
    /// The panels the user opened or closed (View menu, close button, O), by name: kept over the
    /// defaults and over panels opening when used.
    std::map<std::string, bool> panel_choices;
    Columns columns;
    std::vector<Rect> panel_rects;   ///< this frame's place of each panel in a column (panel_list() order)
    std::vector<bool> moved;         ///< lists standing in the other column to balance them (panel_list() order)
    Pick pick;                       ///< the last disk clicked (the inspector)
    Pick ruler;                      ///< the one clicked before it: the inspector measures from it to `pick`
    std::vector<int> picked_events;  ///< trace events whose node holds the picked disk
    FitTable fit;
    Recursion recursion;  ///< of state.trace at recursion_revision
    std::uint64_t recursion_revision = 0;
    std::vector<std::string> dropped;     ///< files dropped on the window, opened on the next frame
    std::vector<std::string> data_files;  ///< the Open panel's listing of the data folder (relative names)
    bool data_listed = false;
    std::string open_filter;
    std::string open_status;  ///< the last file opened, or why it could not be
    std::string save_path = "scene.json";
    std::string status;  ///< last message (saved, errors)
    bool request_frame_all = false;
    ViewPreset request_view = ViewPreset::None;
    bool request_quit = false;
    bool show_help = false;   ///< the Shortcuts window (F1 or ?)
    bool reveal_step = true;  ///< the recursion view unfolds to the shown step once
    float menu_height = 0;    ///< the main menu bar's height (panels start below it)
};

/// The viewer's compact dark style (call once after ImGui::CreateContext).
void apply_style();

void draw_panels(State& state, Ui& ui);

/// The panels a fresh window opens on `state`: a scene's Scene, Query, Trace and Recursion; a crowd's
/// Scene and Crowd, with Query, Trace and Recursion once a candidate's query is opened. The user's own
/// `choices` (Ui::panel_choices) go over them.
PanelsOpen default_panels(const State& state, const std::map<std::string, bool>& choices = {});
/// Opens a panel as it is used (a pick opens the Inspector) unless the user closed it themselves.
void open_when_used(Ui& ui, bool PanelsOpen::*panel);
/// Records the user's own choice for a panel (and applies it).
void choose_panel(Ui& ui, bool PanelsOpen::*panel, bool open);

/// A disk clicked in the 3D view: it becomes the pick, the previous pick the ruler's other end, and
/// when it belongs to the query's clips the trace goes to the last event whose node holds it.
void click_disk(State& state, Ui& ui, const Pick& pick);
/// A click on the query's box `node` of clip `clip` (away from any disk): its events are selected and
/// the trace goes to the last of them.
void click_box(State& state, Ui& ui, int clip, std::int32_t node);

// One file each (panels.cpp draws them in order; widgets.h holds what several share).
void main_menu(State& state, Ui& ui);
void scene_panel(State& state, Ui& ui);
void query_panel(State& state, Ui& ui);
void trace_panel(State& state, Ui& ui);
void recursion_panel(State& state, Ui& ui);
void outcome_strip(State& state, Ui& ui);  ///< under the Trace panel's step slider
void tree_fit_panel(State& state, Ui& ui);
void inspector_panel(State& state, Ui& ui);
void crowd_panel(State& state, Ui& ui);
void timeline_panel(State& state, Ui& ui);
void open_panel(State& state, Ui& ui);
/// Opens the files dropped on the window; what happened goes to ui.open_status.
void open_dropped(State& state, Ui& ui);
/// The clip files under `dir` (every extension load_clip reads, io::is_clip_file), relative to it with
/// '/' separators, sorted; empty when `dir` is empty or unreadable. The Open panel's listing.
std::vector<std::string> list_clip_files(const std::string& dir);

/// Saves the scene (placements and camera included) to ui.save_path: the Scene panel's save button and
/// File > Save scene. The outcome goes to ui.status.
void save_to_path(State& state, Ui& ui);

/// Moves to trace step k (clamped) and, with cursor_at_step, puts the time cursor on it.
void go_to_step(State& state, Ui& ui, int k);
/// Advances the trace while playing, and a crowd's time cursor while it plays.
void update_playback(State& state, Ui& ui, double seconds);

}  // namespace mobb::viewer
