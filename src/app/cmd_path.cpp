// mobb path FILE: the clip's path as CSV (t, x, y, r in seconds and metres).
#include <cstdio>

#include "cli.h"

namespace mobb::app {

void add_path(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("path", "Print a clip's path as CSV: t,x,y,r (seconds, metres)");
    auto file = std::make_shared<std::string>();
    auto load = std::make_shared<LoadArgs>();
    cmd->add_option("FILE", *file, "BVH or glTF/GLB file")->required();
    load->add_to(*cmd);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            const Path path = load_reported(*file, load->options()).path;
            out << "t,x,y,r\n";
            char line[128];
            for (std::size_t i = 0; i < path.size(); ++i) {
                const Sample& s = path.samples[i];
                std::snprintf(line, sizeof line, "%.6f,%.6f,%.6f,%.6f\n", double(i) * path.dt, s.x, s.y, s.r);
                out << line;
            }
        });
    });
}

}  // namespace mobb::app
