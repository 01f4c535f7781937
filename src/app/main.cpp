// mobb: exact space-time collision queries between motion-capture clips (MOBB / UMOBB trees).
#include <exception>
#include <iostream>

#include "cli.h"

namespace {

int run(int argc, char** argv) {
    using namespace mobb::app;
    CLI::App app{"mobb: exact space-time collision detection between motion-capture characters"};
    app.require_subcommand(1);
    int exit_code = kOk;
    add_info(app, exit_code);
    add_path(app, exit_code);
    add_tree(app, exit_code);
    add_query(app, exit_code);
    add_batch(app, exit_code);
    add_crowd_commands(app, exit_code);
    add_record_commands(app, exit_code);
    add_scenario_commands(app, exit_code);
    add_bench_commands(app, exit_code);
    add_export_commands(app, exit_code);
#ifdef MOBB_WITH_VIEWER
    add_view_commands(app, exit_code);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);  // prints help or the usage error
        return code == 0 ? kOk : kUsage;
    }
    return exit_code;
}

}  // namespace

// Each subcommand reports its own errors (guarded() in cli.cpp); what escapes them (out of memory, an
// error in building the command line) gets the same one line, not std::terminate's abort.
int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return mobb::app::kBadInput;
    }
}
