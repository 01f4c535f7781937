#include "state.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "crowd_view.h"
#include "grid_layer.h"
#include "mobb/core/assert.h"
#include "random_walk.h"
#include "renderer.h"
#include "space.h"

namespace mobb::viewer {

static LoadedClip load_clip(const SceneClip& c, std::size_t index) {
    LoadedClip out;
    if (c.walk) {
        out.name = "walk " + std::to_string(c.walk->seed);
        return out;
    }
    const std::string file = io::resolve_data_file(c.file);
    out.clip = std::make_shared<io::Clip>(io::load_clip(file, io::parse_load_options(c.load)));
    if (out.clip->path.samples.empty()) throw io::LoadError(file + ": no samples left after frames / fps");
    out.name = std::filesystem::path(c.file).filename().string();
    (void)index;
    return out;
}

static Path path_of(const State& s, std::size_t k) {
    if (k < s.fixed_paths.size()) return s.fixed_paths[k];
    if (s.clips[k].clip) return s.clips[k].clip->path;
    if (k < s.scene.clips.size()) return random_walk(*s.scene.clips[k].walk);
    RandomWalk w = s.scene.generate.walk;
    w.seed += unsigned(k - s.scene.clips.size());
    return random_walk(w);
}

State load_state(const Scene& scene, float aspect) {
    State s;
    s.scene = scene;
    for (std::size_t k = 0; k < scene.clips.size(); ++k) {
        s.clips.push_back(load_clip(scene.clips[k], k));
        s.places.push_back(scene.clips[k].place);
    }
    const int side = int(std::ceil(std::sqrt(double(scene.generate.count))));
    for (int k = 0; k < scene.generate.count; ++k) {
        LoadedClip c;
        c.name = "walk " + std::to_string(scene.generate.walk.seed + unsigned(k));
        s.clips.push_back(std::move(c));
        const int column = k % side, row = k / side;
        s.places.push_back({double(column) * scene.generate.spacing, double(row) * scene.generate.spacing, 0, 0});
    }
    rebuild_trees(s);
    if (scene.camera)
        s.camera = *scene.camera;
    else
        frame_all(s, aspect);
    return s;
}

int add_clip_file(State& s, const std::string& file) {
    // A crowd's clips are its agents, indexed by their tracks: no room for one more.
    if (s.crowd) throw io::LoadError(file + ": clip files open into scenes, not into a crowd record");
    SceneClip c;
    c.file = io::data_relative(std::filesystem::absolute(file).string());
    LoadedClip loaded = load_clip(c, 0);
    loaded.tree = std::make_unique<Tree>(Tree::build(loaded.clip->path, s.scene.tree));
    const int at = int(s.scene.clips.size());
    s.scene.clips.push_back(c);
    s.clips.insert(s.clips.begin() + at, std::move(loaded));
    s.places.insert(s.places.begin() + at, c.place);
    for (int* q : {&s.scene.query_a, &s.scene.query_b})
        if (*q >= at) ++*q;  // generated walks moved up by one
    const int n = int(s.clips.size());
    if (s.scene.query_a < 0 || s.scene.query_a >= n)
        s.scene.query_a = at;
    else if ((s.scene.query_b < 0 || s.scene.query_b >= n) && s.scene.query_a != at)
        s.scene.query_b = at;
    run_query(s);
    return at;
}

void rebuild_trees(State& s) {
    for (std::size_t k = 0; k < s.clips.size(); ++k)
        s.clips[k].tree = std::make_unique<Tree>(Tree::build(path_of(s, k), s.scene.tree));
    run_query(s);
}

void run_query(State& s) {
    ++s.revision;
    s.trace.clear();
    s.stats = {};
    s.hit = {};
    s.answer = false;
    s.queried = false;
    s.clearance.clear();
    const int a = s.scene.query_a, b = s.scene.query_b, n = int(s.clips.size());
    if (a < 0 || b < 0 || a >= n || b >= n || a == b) return;
    s.answer = collide(*s.clips[std::size_t(a)].tree, s.places[std::size_t(a)], *s.clips[std::size_t(b)].tree,
                       s.places[std::size_t(b)], &s.stats, &s.trace, &s.hit);
    s.clearance = clearance(s.clips[std::size_t(a)].tree->path(), s.places[std::size_t(a)],
                            s.clips[std::size_t(b)].tree->path(), s.places[std::size_t(b)]);
    s.queried = true;
}

namespace {

/// What the renderer draws but the crowd's skeletons (frame_of poses them).
render::Frame unposed_frame(const State& s) {
    render::Frame f;
    Colouring& colouring = *s.colouring;
    update_colouring(s, colouring);
    for (std::size_t k = 0; k < s.clips.size(); ++k) {
        render::ClipView v;
        v.tree = s.clips[k].tree.get();
        if (s.clips[k].clip) {
            v.animation = &s.clips[k].clip->animation;
            v.up = s.clips[k].clip->up;
        }
        v.place = s.places[k];
        v.color = k < s.colors.size() ? s.colors[k] : render::clip_color(int(k));
        v.visible = !s.clips[k].hidden && (k >= s.scene.clips.size() || s.scene.clips[k].visible);
        if (k < colouring.samples.size() && !colouring.samples[k].empty()) v.sample_values = &colouring.samples[k];
        if (k < colouring.nodes.size() && !colouring.nodes[k].empty()) v.node_values = &colouring.nodes[k];
        f.clips.push_back(v);
    }
    f.layers = s.scene.layers;
    f.time_scale = s.scene.time_scale;
    f.cursor = s.scene.cursor;
    f.window = s.scene.window;
    f.skeleton_scale = s.scene.skeleton_scale;
    f.multisample = s.scene.multisample;
    f.trace = {&s.trace, shown_step(s), s.scene.query_a, s.scene.query_b};
    if (s.crowd) f.prisms = crowd_prisms(*s.crowd, s.scene.cursor);
    if (s.crowd) f.extent = crowd_extent(*s.crowd);
    f.revision = s.revision;
    f.disk_scale = colouring.disk_scale;
    f.box_scale = colouring.box_scale;
    f.colour_revision = colouring.serial;
    return f;
}

}  // namespace

namespace {

/// The eight corners of a space-time box in the GL world.
std::vector<glm::vec3> gl_corners(const render::Bounds& b, double time_scale) {
    glm::vec3 lo, hi;
    render::gl_bounds(b, time_scale, lo, hi);
    std::vector<glm::vec3> out;
    out.reserve(10);  // frame_all adds two more
    for (int k = 0; k < 8; ++k) out.emplace_back((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    return out;
}

}  // namespace

void frame_all(State& s, float aspect) {
    const render::Frame f = unposed_frame(s);  // the bounds hold no skeleton: a crowd's need not be posed
    const render::Bounds b = render::scene_bounds(f);
    if (b.empty) return;
    // The scene's space-time box and the time axis, which stands at the grid's corner (grid_bounds, up to
    // a metre past the scene), rather than the whole grid.
    std::vector<glm::vec3> points = gl_corners(b, s.scene.time_scale);
    const render::Bounds grid = render::grid_bounds(b);
    for (const double t : {grid.lo.z, grid.hi.z})
        points.push_back(render::to_gl(grid.lo.x, grid.lo.y, t, s.scene.time_scale));
    // The axis's labels and title stand a little outside it.
    constexpr float kLabelRoom = 1.08f;
    s.camera.frame(points, aspect);
    s.camera.distance *= kLabelRoom;
}

void frame_region(State& s, double x0, double y0, double x1, double y1, float aspect) {
    MOBB_ASSERT(x0 < x1 && y0 < y1);
    double t0 = s.scene.cursor - s.scene.window, t1 = s.scene.cursor + s.scene.window;
    if (s.scene.window <= 0) {
        const render::Bounds b = render::scene_bounds(unposed_frame(s));
        t0 = b.empty ? 0 : b.lo.z, t1 = b.empty ? 1 : b.hi.z;
    }
    render::Bounds b;
    b.add({x0, y0, t0});
    b.add({x1, y1, t1});
    s.camera.frame(gl_corners(b, s.scene.time_scale), aspect);
}

void sync_scene(State& s) {
    for (std::size_t k = 0; k < s.scene.clips.size(); ++k) s.scene.clips[k].place = s.places[k];
    s.scene.camera = s.camera;
}

int shown_step(const State& s) {
    if (s.scene.step < 0 || s.trace.empty()) return -1;
    return std::min(s.scene.step, int(s.trace.size()) - 1);
}

render::Frame frame_of(const State& s) {
    render::Frame f = unposed_frame(s);
    // A crowd's agents carry no animation of their own: their poses come from the graph's sources.
    if (s.crowd && s.scene.layers.skeletons) f.posed = agent_skeletons(*s.crowd, s.scene.cursor, s.colors, &f.prisms);
    return f;
}

}  // namespace mobb::viewer
