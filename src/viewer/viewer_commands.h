// Registers `mobb view`, `mobb render` and `mobb export-gltf` (called by main.cpp).
#pragma once
#include <CLI/CLI.hpp>

namespace mobb::app {

void add_viewer_commands(CLI::App& app, int& exit_code);

}  // namespace mobb::app
