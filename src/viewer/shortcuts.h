// The viewer's keyboard shortcuts and mouse gestures in one table: the window's keyboard handler runs
// it, the Shortcuts window (F1 or ?) lists it, and a test checks that no two entries share a key.
#pragma once
#include <cstdint>
#include <vector>

#include "panels.h"
#include "state.h"

namespace mobb::viewer {

enum class Command : std::uint8_t {
    TogglePlay,
    StepForward,
    StepBack,
    FirstStep,
    LastStep,
    FrameAll,
    TopView,
    SideView,
    OpenFiles,
    ToggleLeftColumn,
    ToggleRightColumn,
    ToggleColumns,
    ClearPicks,
    Quit,
    ToggleHelp,
};

struct Shortcut {
    int key = 0;          ///< GLFW key code
    bool shift = false;   ///< only with Shift held (and the others only without)
    bool repeat = false;  ///< fires again while the key is held
    Command command = Command::ToggleHelp;
    const char* keys = "";  ///< as the Shortcuts window shows it: "Space", "Shift+/ (?)"
    const char* what = "";
};
const std::vector<Shortcut>& shortcuts();

/// The shortcut a key event runs: `repeat` for the window system's auto-repeat of a held key (only
/// shortcuts marked repeat answer it). Null when none.
const Shortcut* find_shortcut(int key, bool shift, bool repeat);

/// A mouse gesture over the 3D view (handled by the window's mouse code), for the Shortcuts window.
struct Gesture {
    const char* input = "";
    const char* what = "";
};
const std::vector<Gesture>& gestures();

/// Carries out a command: trace steps and playback on the state, camera moves as requests in `ui`.
void run_command(Command command, State& state, Ui& ui);

/// The Shortcuts window, while ui.show_help (closable).
void shortcuts_window(Ui& ui);

}  // namespace mobb::viewer
