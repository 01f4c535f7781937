// mobb info FILE: what a clip is made of and what the loader decided.
#include <algorithm>
#include <cmath>
#include <iomanip>

#include "cli.h"

namespace mobb::app {

namespace {

double ground_length(const Path& p) {
    double len = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
        len += std::hypot(p.samples[i].x - p.samples[i - 1].x, p.samples[i].y - p.samples[i - 1].y);
    return len;
}

void print_info(std::ostream& out, const io::Clip& clip) {
    const io::Skeleton& sk = clip.animation.skeleton;
    const int end_sites = int(std::count(sk.end_site.begin(), sk.end_site.end(), true));
    std::vector<double> r;
    for (const Sample& s : clip.path.samples) r.push_back(s.r);
    std::sort(r.begin(), r.end());
    out << std::fixed << std::setprecision(3);
    out << "file: " << clip.file << "\n";
    out << "skeleton: " << sk.size() - end_sites << " joints + " << end_sites << " end sites, root "
        << sk.names[std::size_t(sk.root)] << "\n";
    out << "frames: " << clip.path.size() << " samples (file: " << clip.source_frames << " frames at "
        << std::setprecision(2) << 1.0 / clip.source_dt << " Hz)\n";
    out << std::setprecision(3) << "rate: " << 1.0 / clip.path.dt << " Hz (dt " << std::setprecision(6) << clip.path.dt
        << " s)\n";
    out << std::setprecision(3) << "duration: " << clip.path.duration() << " s\n";
    out << "scale: " << std::setprecision(6) << clip.scale << " m per unit (" << clip.scale_reason << ")\n";
    out << "up: " << (clip.up == io::UpAxis::Y ? "y" : "z") << "\n";
    out << std::setprecision(3) << "root ground path: " << ground_length(clip.path) << " m\n";
    out << "r: min " << r.front() << " median " << r[r.size() / 2] << " max " << r.back() << " m\n";
    out << "warnings: " << clip.warnings.size() << "\n";
    for (const std::string& w : clip.warnings) out << "  " << w << "\n";
}

}  // namespace

void add_info(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("info", "Skeleton, frames, rate, duration, scale, path length and radii of a clip");
    auto file = std::make_shared<std::string>();
    auto load = std::make_shared<LoadArgs>();
    cmd->add_option("FILE", *file, "BVH or glTF/GLB file")->required();
    load->add_to(*cmd);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) { print_info(out, load_reported(*file, load->options())); });
    });
}

}  // namespace mobb::app
