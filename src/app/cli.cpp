#include "cli.h"

#include "mobb/core/angle.h"

#include <cmath>
#include <iostream>
#include <vector>

namespace mobb::app {

void LoadArgs::add_to(CLI::App& cmd) {
    cmd.add_option("--up", text.up, "Up axis of BVH data (and files that do not state it): y or z")
        ->check(CLI::IsMember({"y", "z"}))
        ->capture_default_str();
    cmd.add_option("--scale", text.scale, "Metres per file unit, or auto (infer from the skeleton's height)")
        ->capture_default_str();
    cmd.add_option("--frames", text.frames, "Keep frames A..B-1, written A:B");
    cmd.add_option("--fps", text.fps, "Resample to F samples per second (frame at or just below each time)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--skin", text.skin, "glTF: skin index")->check(CLI::NonNegativeNumber);
    cmd.add_option("--animation", text.animation, "glTF, FBX: animation name (default: the first)");
    cmd.add_option("--root", text.root, "Joint projected on the ground (default: the skeleton's root)");
}

void TreeArgs::add_to(CLI::App& cmd, bool allow_brute) {
    std::vector<std::string> types;
    for (const TreeTypeName& t : kTreeTypes) types.push_back(t.name);
    if (allow_brute) types.push_back("brute");
    cmd.add_option("--tree", type, "Tree type")->check(CLI::IsMember(types))->capture_default_str();
    cmd.add_option("--nmin", n_min, "Most samples in a leaf (n_min)")
        ->check(CLI::Range(1, 1 << 20))
        ->capture_default_str();
    cmd.add_option("--fit", fit, "MOBB axis fit: chord (paper) or pca")
        ->check(CLI::IsMember({"chord", "pca"}))
        ->capture_default_str();
}

TreeOptions TreeArgs::options() const { return parse_tree_options(brute() ? "mobb" : type, n_min, fit); }

io::Clip load_reported(const std::string& file, const io::LoadOptions& options) {
    io::Clip clip = io::load_clip(file, options);
    std::cerr << file << ": scale " << clip.scale << " m per unit (" << clip.scale_reason << ")\n";
    for (const std::string& w : clip.warnings) std::cerr << "warning: " << w << "\n";
    if (clip.path.samples.empty()) throw io::LoadError(file + ": no samples left after --frames / --fps");
    return clip;
}

const io::Clip& ClipCache::clip(const std::string& file) {
    auto& slot = clips_[file];
    if (!slot) slot = std::make_unique<io::Clip>(load_reported(file, load_));
    return *slot;
}

const Tree& ClipCache::tree(const std::string& file) {
    auto& slot = trees_[file];
    if (!slot) slot = std::make_unique<Tree>(Tree::build(clip(file).path, tree_));
    return *slot;
}

Placement parse_placement(const std::string& text, const std::string& what) {
    std::vector<double> v;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        v.push_back(io::parse_number(text.substr(start, comma - start), what));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (v.size() != 4)
        throw InputError(what + ": expected x,y,theta,t0 (metres, degrees, seconds), got '" + text + "'");
    return {v[0], v[1], radians(v[2]), v[3]};
}

int guarded(const std::function<void(std::ostream& out)>& body) {
    std::ostringstream out;
    try {
        body(out);
    } catch (const io::LoadError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kBadInput;
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kBadInput;
    } catch (const std::invalid_argument& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kBadInput;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return kBadInput;
    }
    std::cout << out.str() << std::flush;
    return kOk;
}

void parse_world(const std::string& text, double& w, double& h) {
    const auto x = text.find('x');
    try {
        std::size_t u1 = 0, u2 = 0;
        if (x == std::string::npos) throw std::invalid_argument("");
        w = std::stod(text.substr(0, x), &u1);
        h = std::stod(text.substr(x + 1), &u2);
        if (u1 != x || u2 != text.size() - x - 1 || !(w > 0) || !(h > 0) || !std::isfinite(w) || !std::isfinite(h))
            throw std::invalid_argument("");
    } catch (const std::exception&) {
        throw InputError("--world: expected WxH in metres (e.g. 30x40), got '" + text + "'");
    }
}

std::function<void(double)> progress_bar(const std::string& label) {
    auto last = std::make_shared<int>(-1);
    return [label, last](double f) {
        const int pct = int(f * 100.0);
        if (pct == *last) return;
        *last = pct;
        const int w = 30, filled = pct * w / 100;
        std::cerr << "\r" << label << " [" << std::string(std::size_t(filled), '#')
                  << std::string(std::size_t(w - filled), ' ') << "] " << pct << " %" << (pct >= 100 ? "\n" : "")
                  << std::flush;
    };
}

}  // namespace mobb::app
