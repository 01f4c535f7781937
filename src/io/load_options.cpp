// Loader options from their text (command line, scene files) to LoadOptions.
#include <cmath>
#include <stdexcept>

#include "mobb/io/load.h"

namespace mobb::io {

namespace {

void parse_frames(const std::string& frames, LoadOptions& o) {
    const auto colon = frames.find(':');
    if (colon == std::string::npos) throw std::invalid_argument("--frames: expected A:B, got '" + frames + "'");
    const double a = parse_number(frames.substr(0, colon), "--frames A");
    const double b = colon + 1 < frames.size() ? parse_number(frames.substr(colon + 1), "--frames B") : -1;
    if (a < 0 || a != std::floor(a) || (b >= 0 && (b != std::floor(b) || b <= a)) || b > 2e9)
        throw std::invalid_argument("--frames: expected whole numbers 0 <= A < B, got '" + frames + "'");
    o.frame_begin = int(a);
    o.frame_end = int(b);
}

}  // namespace

double parse_number(const std::string& text, const std::string& what) {
    std::size_t used = 0;
    double v = 0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || !std::isfinite(v))
        throw std::invalid_argument(what + ": '" + text + "' is not a finite number");
    return v;
}

LoadOptions parse_load_options(const LoadOptionText& text) {
    LoadOptions o;
    if (text.up != "y" && text.up != "z") throw std::invalid_argument("--up: expected y or z, got '" + text.up + "'");
    o.up = text.up == "z" ? UpAxis::Z : UpAxis::Y;
    if (text.scale != "auto") {
        o.scale = parse_number(text.scale, "--scale");
        if (*o.scale <= 0) throw std::invalid_argument("--scale: must be positive");
    }
    if (!text.frames.empty()) parse_frames(text.frames, o);
    if (text.fps > 0) o.fps = text.fps;
    o.skin = text.skin;
    o.animation = text.animation;
    o.root = text.root;
    return o;
}

}  // namespace mobb::io
