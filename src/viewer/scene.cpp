#include "scene.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "mobb/core/angle.h"
#include "space.h"
#include "viewer_error.h"

namespace mobb::viewer {

namespace {

using nlohmann::json;

/// Typed access to one JSON object with the place named in every error, and unknown keys rejected.
class Reader {
public:
    Reader(const json& object, std::string where, const std::set<std::string>& keys)
        : j_(object), where_(std::move(where)) {
        if (!j_.is_object()) fail(where_, "expected an object");
        for (const auto& item : j_.items())
            if (!keys.count(item.key())) fail(at(item.key()), "unknown key");
    }

    [[noreturn]] static void fail(const std::string& where, const std::string& message) {
        throw ViewerError(where + ": " + message);
    }
    std::string at(const std::string& key) const { return where_ + "." + key; }
    bool has(const char* key) const { return j_.contains(key); }
    const json& raw(const char* key) const { return j_.at(key); }

    double number(const char* key, double fallback) const {
        if (!has(key)) return fallback;
        return finite(j_.at(key), at(key));
    }
    /// A number within lo..hi (both allowed).
    double number(const char* key, double fallback, double lo, double hi) const {
        const double v = number(key, fallback);
        if (!(v >= lo && v <= hi)) fail(at(key), "expected a number in " + range(lo, hi) + ", got " + text(v));
        return v;
    }
    /// A number over 0 and at most hi.
    double positive(const char* key, double fallback, double hi) const {
        const double v = number(key, fallback);
        if (!(v > 0 && v <= hi)) fail(at(key), "expected a number over 0 and at most " + text(hi) + ", got " + text(v));
        return v;
    }
    int integer(const char* key, int fallback, int lo, int hi) const {
        if (!has(key)) return fallback;
        const json& v = j_.at(key);
        if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
            fail(at(key), "expected a whole number in " + std::to_string(lo) + ".." + std::to_string(hi));
        return int(v.get<long long>());
    }
    bool boolean(const char* key, bool fallback) const {
        if (!has(key)) return fallback;
        if (!j_.at(key).is_boolean()) fail(at(key), "expected true or false");
        return j_.at(key).get<bool>();
    }
    std::string string(const char* key, const std::string& fallback) const {
        if (!has(key)) return fallback;
        if (!j_.at(key).is_string()) fail(at(key), "expected a string");
        return j_.at(key).get<std::string>();
    }
    /// An array of `count` numbers, each within lo..hi; an error names the element (KEY[i]).
    std::vector<double> numbers(const char* key, std::size_t count, double lo, double hi) const {
        const json& v = j_.at(key);
        if (!v.is_array() || v.size() != count)
            fail(at(key), "expected an array of " + std::to_string(count) + " numbers");
        std::vector<double> out;
        for (std::size_t k = 0; k < count; ++k) {
            const std::string place = at(key) + "[" + std::to_string(k) + "]";
            const double x = finite(v[k], place);
            if (!(x >= lo && x <= hi)) fail(place, "expected a number in " + range(lo, hi) + ", got " + text(x));
            out.push_back(x);
        }
        return out;
    }

    static std::string text(double v) {
        char out[32];
        std::snprintf(out, sizeof out, "%g", v);
        return out;
    }
    static std::string range(double lo, double hi) { return text(lo) + ".." + text(hi); }

private:
    static double finite(const json& v, const std::string& place) {
        if (!v.is_number() || !std::isfinite(v.get<double>())) fail(place, "expected a finite number");
        return v.get<double>();
    }

    const json& j_;
    std::string where_;
};

RandomWalk walk_of(const json& j, const std::string& where) {
    Reader r(j, where, {"seconds", "hz", "seed", "random_walks", "spacing"});
    RandomWalk w;
    w.seconds = r.positive("seconds", w.seconds, kMaxWalkSamples / kMinRate);
    w.hz = r.number("hz", w.hz, kMinRate, kMaxRate);
    w.seed = unsigned(r.integer("seed", int(w.seed), 0, 1 << 30));
    // A tree needs a sample; the product is checked for the scene's walks together (parse_scene).
    if (std::llround(w.seconds * w.hz) < 1)
        Reader::fail(r.at("seconds"), "expected at least one sample (seconds x hz)");
    if (w.seconds * w.hz > kMaxWalkSamples)
        Reader::fail(r.at("seconds"), "more than " + Reader::text(kMaxWalkSamples) + " samples (seconds x hz)");
    return w;
}

SceneClip clip_of(const json& j, const std::string& where) {
    Reader r(j, where, {"file", "random_walk", "up", "scale", "frames", "fps", "place", "visible"});
    SceneClip c;
    if (r.has("file") == r.has("random_walk"))
        Reader::fail(where, "expected exactly one of \"file\" and \"random_walk\"");
    c.file = r.string("file", "");
    if (r.has("random_walk")) {
        if (j.at("random_walk").contains("random_walks") || j.at("random_walk").contains("spacing"))
            Reader::fail(r.at("random_walk"), "unknown key");
        c.walk = walk_of(j.at("random_walk"), r.at("random_walk"));
    }
    c.load.up = r.string("up", c.load.up);
    if (c.load.up != "y" && c.load.up != "z") Reader::fail(r.at("up"), "expected \"y\" or \"z\"");
    if (r.has("scale")) {
        const json& s = j.at("scale");
        if (s.is_number()) {
            char text[64];
            std::snprintf(text, sizeof text, "%.17g", r.number("scale", 1, kMinScale, kMaxScale));
            c.load.scale = text;
        } else if (s.is_string() && s.get<std::string>() == "auto") {
            c.load.scale = "auto";
        } else {
            Reader::fail(r.at("scale"), "expected a number or \"auto\"");
        }
    }
    c.load.frames = r.string("frames", "");
    try {  // checked here too, so that a bad range names the scene file and the key
        io::LoadOptionText frames;
        frames.frames = c.load.frames;
        (void)io::parse_load_options(frames);
    } catch (const std::exception& e) {
        Reader::fail(r.at("frames"), e.what());
    }
    c.load.fps = r.has("fps") ? r.number("fps", 0, kMinRate, kMaxRate) : 0;
    if (r.has("place")) {  // x, y (m), theta (degrees), t0 (s): the Query panel's ranges
        const auto p = r.numbers("place", 4, -kFar, kFar);
        c.place = {p[0], p[1], radians(p[2]), p[3]};
    }
    c.visible = r.boolean("visible", true);
    return c;
}

void layers_of(const json& j, const std::string& where, render::Layers& l) {
    Reader r(j, where,
             {"grid", "labels", "disks", "disks_translucent", "boxes", "box_faces", "all_levels", "level", "levels",
              "cursor", "skeletons", "bodies", "trace", "disk_colour", "box_colour", "colour_bar"});
    l.grid = r.boolean("grid", l.grid);
    l.labels = r.boolean("labels", l.labels);
    l.disks = r.boolean("disks", l.disks);
    l.disks_translucent = r.boolean("disks_translucent", l.disks_translucent);
    l.boxes = r.boolean("boxes", l.boxes);
    l.box_faces = r.boolean("box_faces", l.box_faces);
    l.all_levels = r.boolean("all_levels", l.all_levels);
    l.level = r.integer("level", l.level, 0, 63);
    l.levels = r.integer("levels", l.levels, 1, 64);
    l.cursor = r.boolean("cursor", l.cursor);
    l.skeletons = r.boolean("skeletons", l.skeletons);
    l.bodies = r.boolean("bodies", l.bodies);
    l.trace = r.boolean("trace", l.trace);
    try {
        if (r.has("disk_colour"))
            l.disk_colour = render::parse_disk_colour(r.string("disk_colour", to_string(l.disk_colour)));
    } catch (const std::invalid_argument& e) {
        Reader::fail(r.at("disk_colour"), e.what());
    }
    try {
        if (r.has("box_colour"))
            l.box_colour = render::parse_box_colour(r.string("box_colour", to_string(l.box_colour)));
    } catch (const std::invalid_argument& e) {
        Reader::fail(r.at("box_colour"), e.what());
    }
    l.colour_bar = r.boolean("colour_bar", l.colour_bar);
}

render::Camera camera_of(const json& j, const std::string& where, double time_scale) {
    Reader r(j, where, {"target", "yaw", "pitch", "distance", "fov"});
    render::Camera c;
    if (r.has("target")) {
        const auto t = r.numbers("target", 3, -kFar, kFar);
        c.target = render::to_gl(t[0], t[1], t[2], time_scale);
    }
    c.yaw = float(r.number("yaw", c.yaw, -kMaxYaw, kMaxYaw));
    c.pitch = float(r.number("pitch", c.pitch, -89.0, 89.9));  // Camera::orbit's range
    c.distance = float(r.positive("distance", c.distance, kMaxCameraDistance));
    c.fov = float(r.number("fov", c.fov, kMinFov, kMaxFov));
    return c;
}

/// The random walks' samples together, and the query's clips: indices of the scene's clips (its own,
/// then the generated walks), two different ones or -1 for none.
void check_clips(const Scene& s, const Reader& r) {
    double samples = double(s.generate.count) * s.generate.walk.seconds * s.generate.walk.hz;
    for (const SceneClip& c : s.clips)
        if (c.walk) samples += c.walk->seconds * c.walk->hz;
    if (samples > kMaxWalkSamples)
        Reader::fail(r.at(s.generate.count > 0 ? "generate" : "clips"),
                     "more than " + Reader::text(kMaxWalkSamples) + " samples in the random walks together");
    const int clips = int(s.clips.size()) + s.generate.count;
    const std::string where = r.at("query");
    for (const auto& [key, index] : {std::pair{"a", s.query_a}, std::pair{"b", s.query_b}})
        if (index >= clips)
            Reader::fail(where + "." + key, "clip " + std::to_string(index) + " past the scene's " +
                                                std::to_string(clips) + " clips (-1 for none)");
    if (s.query_a >= 0 && s.query_a == s.query_b) Reader::fail(where + ".b", "expected a clip other than a's");
    if ((s.query_a < 0) != (s.query_b < 0))
        Reader::fail(where + (s.query_a < 0 ? ".a" : ".b"), "expected a clip (-1 for none only with the other)");
}

}  // namespace

Scene parse_scene(const json& j, const std::string& file) {
    Reader r(j, file, {"clips", "generate", "tree", "query", "layers", "time", "skeleton_scale", "camera", "image"});
    Scene s;
    if (r.has("clips")) {
        const json& clips = j.at("clips");
        if (!clips.is_array()) Reader::fail(r.at("clips"), "expected an array");
        for (std::size_t k = 0; k < clips.size(); ++k)
            s.clips.push_back(clip_of(clips[k], r.at("clips") + "[" + std::to_string(k) + "]"));
    }
    if (r.has("generate")) {
        const Reader g(j.at("generate"), r.at("generate"), {"random_walks", "seconds", "hz", "seed", "spacing"});
        s.generate.count = g.integer("random_walks", 0, 0, 10000);
        s.generate.walk = walk_of(j.at("generate"), r.at("generate"));
        // The walks stand on a square grid from the origin, which must stay within kFar.
        const double side = std::ceil(std::sqrt(double(s.generate.count)));
        s.generate.spacing = g.positive("spacing", s.generate.spacing, kFar / std::max(1.0, side - 1));
    }
    if (r.has("tree")) {
        const Reader t(j.at("tree"), r.at("tree"), {"type", "n_min", "fit"});
        try {
            s.tree.type = parse_tree_type(t.string("type", "mobb"));
        } catch (const std::exception&) {
            Reader::fail(t.at("type"), "expected one of " + tree_type_names());
        }
        s.tree.n_min = t.integer("n_min", s.tree.n_min, 1, 1 << 20);
        const std::string fit = t.string("fit", "chord");
        if (fit != "chord" && fit != "pca") Reader::fail(t.at("fit"), "expected \"chord\" or \"pca\"");
        s.tree.fit = fit == "pca" ? AxisFit::Pca : AxisFit::Chord;
    }
    if (r.has("query")) {
        const Reader q(j.at("query"), r.at("query"), {"a", "b", "step"});
        s.query_a = q.integer("a", s.query_a, -1, 1 << 20);
        s.query_b = q.integer("b", s.query_b, -1, 1 << 20);
        s.step = q.integer("step", s.step, -1, 1 << 30);
    }
    if (r.has("layers")) layers_of(j.at("layers"), r.at("layers"), s.layers);
    if (r.has("time")) {
        const Reader t(j.at("time"), r.at("time"), {"scale", "cursor", "window"});
        s.time_scale = t.number("scale", s.time_scale, kMinTimeScale, kMaxTimeScale);
        s.cursor = t.number("cursor", s.cursor, -kFar, kFar);
        s.window = t.number("window", s.window, 0, kFar);
    }
    s.skeleton_scale = r.number("skeleton_scale", s.skeleton_scale, kMinSkeletonScale, kMaxSkeletonScale);
    if (r.has("camera")) s.camera = camera_of(j.at("camera"), r.at("camera"), s.time_scale);
    if (r.has("image")) {
        const Reader im(j.at("image"), r.at("image"), {"width", "height", "multisample"});
        s.width = im.integer("width", s.width, 16, 8192);
        s.height = im.integer("height", s.height, 16, 8192);
        s.multisample = im.boolean("multisample", s.multisample);
    }
    check_clips(s, r);
    return s;
}

Scene load_scene(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw ViewerError(file + ": cannot open scene file");
    std::stringstream text;
    text << in.rdbuf();
    json j;
    try {
        j = json::parse(text.str());
    } catch (const json::parse_error& e) {
        std::string what = e.what();
        const auto pos = what.find("] ");
        throw ViewerError(file + ": " + (pos == std::string::npos ? what : what.substr(pos + 2)));
    }
    return parse_scene(j, file);
}

json scene_json(const Scene& s) {
    json clips = json::array();
    for (const SceneClip& c : s.clips) {
        json o;
        if (c.walk)
            o["random_walk"] = {{"seconds", c.walk->seconds}, {"hz", c.walk->hz}, {"seed", c.walk->seed}};
        else
            o["file"] = c.file;
        if (c.load.up != "y") o["up"] = c.load.up;
        if (c.load.scale != "auto") o["scale"] = std::stod(c.load.scale);
        if (!c.load.frames.empty()) o["frames"] = c.load.frames;
        if (c.load.fps > 0) o["fps"] = c.load.fps;
        o["place"] = {c.place.x, c.place.y, degrees(c.place.theta), c.place.t0};
        if (!c.visible) o["visible"] = false;
        clips.push_back(o);
    }
    const render::Layers& l = s.layers;
    json j = {{"clips", clips},
              {"tree",
               {{"type", to_string(s.tree.type)},
                {"n_min", s.tree.n_min},
                {"fit", s.tree.fit == AxisFit::Pca ? "pca" : "chord"}}},
              {"query", {{"a", s.query_a}, {"b", s.query_b}, {"step", s.step}}},
              {"layers",
               {{"grid", l.grid},
                {"labels", l.labels},
                {"disks", l.disks},
                {"disks_translucent", l.disks_translucent},
                {"boxes", l.boxes},
                {"box_faces", l.box_faces},
                {"all_levels", l.all_levels},
                {"level", l.level},
                {"levels", l.levels},
                {"cursor", l.cursor},
                {"skeletons", l.skeletons},
                {"bodies", l.bodies},
                {"trace", l.trace},
                {"disk_colour", to_string(l.disk_colour)},
                {"box_colour", to_string(l.box_colour)},
                {"colour_bar", l.colour_bar}}},
              {"time", {{"scale", s.time_scale}, {"cursor", s.cursor}, {"window", s.window}}},
              {"skeleton_scale", s.skeleton_scale},
              {"image", {{"width", s.width}, {"height", s.height}}}};
    if (!s.multisample) j["image"]["multisample"] = false;
    if (s.generate.count > 0)
        j["generate"] = {{"random_walks", s.generate.count},
                         {"seconds", s.generate.walk.seconds},
                         {"hz", s.generate.walk.hz},
                         {"seed", s.generate.walk.seed},
                         {"spacing", s.generate.spacing}};
    if (s.camera) {
        const render::Camera& c = *s.camera;
        j["camera"] = {{"target", {c.target.x, -c.target.z, c.target.y / s.time_scale}},
                       {"yaw", c.yaw},
                       {"pitch", c.pitch},
                       {"distance", c.distance},
                       {"fov", c.fov}};
    }
    return j;
}

void save_scene(const Scene& scene, const std::string& file) {
    const std::string tmp = file + ".part";
    {
        std::ofstream out(tmp);
        out << scene_json(scene).dump(2) << "\n";
        if (!out) {
            std::remove(tmp.c_str());
            throw ViewerError(file + ": cannot write scene file");
        }
    }
    if (std::rename(tmp.c_str(), file.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw ViewerError(file + ": cannot write scene file");
    }
}

Scene scene_of_files(const std::vector<std::string>& files) {
    Scene s;
    for (std::size_t k = 0; k < files.size(); ++k) {
        SceneClip c;
        c.file = files[k];
        c.place.theta = double(k) * kPi / 2.0;  // crossing directions; the viewer centres each path
        s.clips.push_back(c);
    }
    if (files.size() < 2) s.query_a = s.query_b = -1;
    s.layers.boxes = true;
    s.layers.level = 2;
    return s;
}

}  // namespace mobb::viewer
