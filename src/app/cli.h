// What every subcommand shares: loader options, placements, tree settings, errors and exit codes.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "mobb/core/path.h"
#include "mobb/core/tree.h"
#include "mobb/io/load.h"

namespace mobb::app {

/// Exit codes: 0 success, 1 bad input (files, placements, data), 2 usage error.
enum Exit { kOk = 0, kBadInput = 1, kUsage = 2 };

/// Bad input that is not a file's fault (a placement string, a batch line). One line.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The loader options of every subcommand: --up, --scale, --frames, --fps, --skin, --animation, --root.
struct LoadArgs {
    io::LoadOptionText text;

    void add_to(CLI::App& cmd);
    io::LoadOptions options() const { return io::parse_load_options(text); }  ///< throws std::invalid_argument
};

/// Tree settings: --tree, --nmin, --fit.
struct TreeArgs {
    std::string type = "mobb";
    int n_min = 10;
    std::string fit = "chord";

    void add_to(CLI::App& cmd, bool allow_brute);
    bool brute() const { return type == "brute"; }
    TreeOptions options() const;
};

/// Loads a clip, reporting the scale chosen and any warnings on stderr (stdout stays data only).
io::Clip load_reported(const std::string& file, const io::LoadOptions& options);

/// Clips and trees by file, each loaded and built once (batch, crowd).
class ClipCache {
public:
    ClipCache(io::LoadOptions load, TreeOptions tree) : load_(std::move(load)), tree_(tree) {}
    const io::Clip& clip(const std::string& file);
    const Tree& tree(const std::string& file);

private:
    io::LoadOptions load_;
    TreeOptions tree_;
    std::map<std::string, std::unique_ptr<io::Clip>> clips_;
    std::map<std::string, std::unique_ptr<Tree>> trees_;
};

/// "x,y,theta,t0" (metres, degrees, seconds) -> placement with theta in radians. Throws InputError.
Placement parse_placement(const std::string& text, const std::string& what);

/// Runs a subcommand body, mapping errors to one line on stderr and an exit code. The body writes
/// its output to `out`, which reaches stdout only on success: no partial output.
int guarded(const std::function<void(std::ostream& out)>& body);

// Each subcommand file registers itself.
void add_info(CLI::App& app, int& exit_code);
void add_path(CLI::App& app, int& exit_code);
void add_tree(CLI::App& app, int& exit_code);
void add_query(CLI::App& app, int& exit_code);
void add_batch(CLI::App& app, int& exit_code);
void add_crowd_commands(CLI::App& app, int& exit_code);     // graph, crowd (cmd_crowd.cpp)
void add_record_commands(CLI::App& app, int& exit_code);    // record convert (cmd_record.cpp)
void add_scenario_commands(CLI::App& app, int& exit_code);  // scenario import (cmd_scenario.cpp)
void add_bench_commands(CLI::App& app, int& exit_code);     // bench ... (cmd_bench.cpp)
void add_export_commands(CLI::App& app, int& exit_code);    // export-crowd (cmd_export.cpp)
void add_view_commands(CLI::App& app, int& exit_code);      // view, render, export-gltf (cmd_view.cpp, with the viewer)

/// "WxH" in metres -> w, h. Throws InputError.
void parse_world(const std::string& text, double& w, double& h);
/// A progress bar on stderr, redrawn when the percentage changes.
std::function<void(double)> progress_bar(const std::string& label);

}  // namespace mobb::app
