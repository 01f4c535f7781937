#include "mobb/io/load.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <system_error>

#include <glm/common.hpp>

#include "mobb/io/assimp_reader.h"

#include "bvh.h"
#include "common.h"
#include "gltf.h"

namespace mobb::io {
namespace {

namespace fs = std::filesystem;

constexpr std::streamoff kMaxFileBytes = std::streamoff(1) << 31;

[[noreturn]] void fail(const std::string& file, const std::string& message) { throw LoadError(file + ": " + message); }

std::string format(const char* pattern, double value) {
    std::array<char, 64> buffer{};
    std::snprintf(buffer.data(), buffer.size(), pattern, value);
    return buffer.data();
}

std::string lower_extension(const std::string& file) {
    std::string ext = fs::path(file).extension().string();
    for (char& c : ext)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return ext;
}

std::string read_file(const std::string& file) {
    std::error_code ec;
    if (fs::is_directory(file, ec)) fail(file, "cannot open: it is a folder");
    // FIFOs and devices could block or never end.
    if (fs::exists(file, ec) && !fs::is_regular_file(file, ec)) fail(file, "cannot open: not a regular file");
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file, "cannot open: " + std::generic_category().message(errno));
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) fail(file, "cannot read: not a regular file");
    if (size > kMaxFileBytes) fail(file, "cannot read: larger than 2 GiB");
    in.seekg(0, std::ios::beg);
    std::string bytes(std::size_t(size), '\0');
    if (!in.read(bytes.data(), size)) fail(file, "cannot read: " + std::generic_category().message(errno));
    return bytes;
}

void check_positive(const std::string& file, const char* option, double value) {
    if (!std::isfinite(value) || value <= 0)
        fail(file, std::string(option) + " " + format("%g", value) + " must be finite and positive");
}

// The standing height in file units: the median over frames of the largest side of the posed
// skeleton's bounding box. The largest side is the height for a standing or walking person (or the
// arm span, about the same), whatever the axes and the root rotation (the CMU files rotate the root
// -90 degrees about X every frame); the median ignores crouching, jumping and stray frames. Neither
// the rest pose nor frame 0 alone will do: the CMU rig's rest pose (every channel zero) is bent and
// only 132.5 units tall, and 001_14 starts crouched (110.8 units). Over the 57 CMU files this gives
// 145.6 to 176.4 units (people 1.46 to 1.76 m tall, per the data's README).
double standing_height(const Animation& anim) {
    const int joints = anim.skeleton.size();
    std::vector<double> sides;
    sides.reserve(std::size_t(anim.frames()));
    for (int f = 0; f < anim.frames(); ++f) {
        glm::dvec3 lo(std::numeric_limits<double>::infinity());
        glm::dvec3 hi(-std::numeric_limits<double>::infinity());
        for (int j = 0; j < joints; ++j) {
            lo = glm::min(lo, anim.at(f, j));
            hi = glm::max(hi, anim.at(f, j));
        }
        const glm::dvec3 side = hi - lo;
        sides.push_back(std::max({side.x, side.y, side.z}));
    }
    if (sides.empty()) return 0;
    const auto middle = sides.begin() + std::ptrdiff_t(sides.size() / 2);
    std::nth_element(sides.begin(), middle, sides.end());
    return *middle;
}

std::string given_reason(double scale) { return "given: " + format("%g", scale) + " m per unit"; }

void load_bvh(Clip& clip, const std::string& text, const LoadOptions& options) {
    const bvh::Document doc = bvh::parse(text, clip.file);
    if (options.scale) {
        clip.scale = *options.scale;
        clip.scale_reason = given_reason(clip.scale);
        clip.animation = bvh::animate(doc, clip.scale);
    } else {
        clip.animation = bvh::animate(doc, 1.0);
        const ScaleGuess guess = guess_scale(standing_height(clip.animation));
        clip.scale = guess.scale;
        clip.scale_reason = guess.reason;
        for (glm::dvec3& p : clip.animation.positions) p *= clip.scale;
    }
    clip.source_dt = doc.frame_time;
}

void load_gltf(Clip& clip, const std::string& bytes, const LoadOptions& options) {
    gltf::Result result = gltf::load(clip.file, bytes, options.skin, options.animation);
    clip.animation = std::move(result.animation);
    clip.warnings = std::move(result.warnings);
    clip.scale = options.scale.value_or(1.0);
    clip.scale_reason = options.scale ? given_reason(clip.scale) : "glTF: metres";
    if (clip.scale != 1.0)
        for (glm::dvec3& p : clip.animation.positions) p *= clip.scale;
    clip.source_dt = clip.animation.dt;
    if (options.up == UpAxis::Z) clip.warnings.push_back(clip.file + ": glTF is Y-up; --up z is ignored");
    clip.up = UpAxis::Y;
}

// Units: --scale, else the unit the file states, else guessed from the standing height like BVH.
void load_assimp(Clip& clip, const std::string& bytes, const LoadOptions& options) {
    assimp::Result result = assimp::load(clip.file, bytes, options);
    clip.animation = std::move(result.animation);
    clip.warnings = std::move(result.warnings);
    clip.up = result.up;
    clip.source_dt = result.source_dt;
    if (options.scale) {
        clip.scale = *options.scale;
        clip.scale_reason = given_reason(clip.scale);
    } else if (result.unit > 0) {
        clip.scale = result.unit;
        clip.scale_reason = result.unit_reason;
    } else {
        const ScaleGuess guess = guess_scale(standing_height(clip.animation));
        clip.scale = guess.scale;
        clip.scale_reason = guess.reason;
    }
    if (clip.scale != 1.0)
        for (glm::dvec3& p : clip.animation.positions) p *= clip.scale;
}

// --root NAME: the joint projected on the ground, for every format.
void choose_root(Clip& clip, const std::string& name) {
    const Skeleton& s = clip.animation.skeleton;
    for (int j = 0; j < s.size(); ++j)
        if (s.names[std::size_t(j)] == name && !s.end_site[std::size_t(j)]) {
            clip.animation.skeleton.root = j;
            return;
        }
    fail(clip.file, "--root: no joint named '" + detail::quote(name) + "' (the skeleton's root is '" +
                        detail::quote(s.names.empty() ? std::string() : s.names[std::size_t(s.root)]) + "')");
}

// Keeps frames [begin, end) of the animation and of source_index.
void keep_frames(Clip& clip, int begin, int end) {
    auto& positions = clip.animation.positions;
    const auto joints = std::ptrdiff_t(clip.animation.skeleton.size());
    positions.erase(positions.begin() + end * joints, positions.end());
    positions.erase(positions.begin(), positions.begin() + begin * joints);
    clip.source_index.erase(clip.source_index.begin() + end, clip.source_index.end());
    clip.source_index.erase(clip.source_index.begin(), clip.source_index.begin() + begin);
}

void select_frames(Clip& clip, const LoadOptions& options) {
    const int n = clip.animation.frames();
    const int begin = options.frame_begin;
    const int end = options.frame_end == -1 ? n : options.frame_end;
    if (begin < 0 || begin >= end || end > n)
        fail(clip.file, "--frames " + std::to_string(begin) + ":" + std::to_string(end) +
                            " is outside the clip (need 0 <= A < B <= " + std::to_string(n) + ")");
    keep_frames(clip, begin, end);
}

// New sample k (time k/F, k/F < duration) takes the frame at or just below k/F; the epsilon makes an
// exact multiple of the frame time land on its own frame despite rounding.
void resample(Clip& clip, double fps) {
    check_positive(clip.file, "--fps", fps);
    Animation& anim = clip.animation;
    const int n = anim.frames();
    const double dt = anim.dt;
    const double count = std::max(1.0, std::ceil(double(n) * dt * fps - 1e-6));
    if (count > detail::kMaxSamples || count * double(anim.skeleton.size()) > double(detail::kMaxPositions))
        fail(clip.file, "--fps " + format("%g", fps) + " gives too many samples");
    const auto joints = std::size_t(anim.skeleton.size());
    std::vector<glm::dvec3> positions;
    std::vector<int> source;
    positions.reserve(std::size_t(count) * joints);
    for (std::size_t k = 0; k < std::size_t(count); ++k) {
        const double frame = std::floor(double(k) / fps / dt + 1e-6);
        const auto f = std::size_t(std::min(frame, double(n - 1)));
        positions.insert(positions.end(), anim.positions.begin() + std::ptrdiff_t(f * joints),
                         anim.positions.begin() + std::ptrdiff_t((f + 1) * joints));
        source.push_back(clip.source_index[f]);
    }
    anim.positions = std::move(positions);
    anim.dt = 1.0 / fps;
    clip.source_index = std::move(source);
}

}  // namespace

ScaleGuess guess_scale(double height) {
    struct Unit {
        const char* name;
        double metres;
    };
    static constexpr std::array<Unit, 4> units = {
        {{"metres", 1.0}, {"centimetres", 0.01}, {"inches", 0.0254}, {"CMU units", 0.056444}}};
    const std::string measured = " (standing height " + format("%.1f", height) + " units)";
    if (!(height > 0) || !std::isfinite(height)) return {1.0, "auto: metres" + measured};
    const Unit* best = &units[0];
    for (const Unit& u : units)
        if (std::abs(std::log(height * u.metres / 1.7)) < std::abs(std::log(height * best->metres / 1.7))) best = &u;
    return {best->metres, std::string("auto: ") + best->name + measured};
}

std::vector<std::string> root_jumps(const Clip& clip, double threshold) {
    constexpr std::size_t kMaxReported = 10;
    std::vector<std::string> out;
    std::size_t jumps = 0;
    const auto& s = clip.path.samples;
    for (std::size_t i = 1; i < s.size(); ++i) {
        const double d = std::hypot(s[i].x - s[i - 1].x, s[i].y - s[i - 1].y);
        if (!(d > threshold)) continue;
        if (++jumps > kMaxReported) continue;
        const bool known = i < clip.source_index.size();
        const int frame = known ? clip.source_index[i] : int(i);
        const int previous = known ? clip.source_index[i - 1] : int(i - 1);
        out.push_back(clip.file + ": frame " + std::to_string(frame) + ": root jumps " + format("%.2f", d) +
                      " m on the ground from frame " + std::to_string(previous) + " (drop frames with --frames)");
    }
    if (jumps > kMaxReported)
        out.push_back(clip.file + ": " + std::to_string(jumps - kMaxReported) + " more root jumps not listed");
    return out;
}

std::vector<std::string> clip_extensions() {
    std::vector<std::string> out = assimp::extensions();
    out.insert(out.end(), {".bvh", ".glb", ".gltf"});
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

bool is_clip_file(const std::string& file) {
    const std::string ext = lower_extension(file);
    return ext == ".bvh" || ext == ".glb" || ext == ".gltf" || assimp::reads(ext);
}

Clip load_clip(const std::string& file, const LoadOptions& options) {
    Clip clip;
    clip.file = file;
    clip.up = options.up;
    const std::string ext = lower_extension(file);
    const bool gltf = ext == ".glb" || ext == ".gltf";
    if (!is_clip_file(file))
        fail(file, "unknown file type '" + detail::quote(ext) +
                       "' (expected .bvh, .glb, .gltf, .fbx, .dae or another format Assimp reads)");
    if (options.scale) check_positive(file, "--scale", *options.scale);
    const std::string bytes = read_file(file);
    if (ext == ".bvh")
        load_bvh(clip, bytes, options);
    else if (gltf)
        load_gltf(clip, bytes, options);
    else
        load_assimp(clip, bytes, options);
    if (!options.root.empty()) choose_root(clip, options.root);

    clip.source_frames = clip.animation.frames();
    clip.source_index.resize(std::size_t(clip.source_frames));
    for (int f = 0; f < clip.source_frames; ++f) clip.source_index[std::size_t(f)] = f;
    select_frames(clip, options);
    if (options.fps) resample(clip, *options.fps);

    clip.path = path_of(clip.animation, clip.up);
    try {
        validate(clip.path);
    } catch (const std::invalid_argument& e) {
        fail(file, std::string("invalid path: ") + e.what());
    }
    const std::vector<std::string> jumps = root_jumps(clip);
    clip.warnings.insert(clip.warnings.end(), jumps.begin(), jumps.end());
    return clip;
}

}  // namespace mobb::io
