// mobb view, mobb render, mobb export-gltf: the viewer layer's subcommands (src/viewer).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <system_error>

#include "cli.h"
#include "context_glfw.h"
#include "crowd_view.h"
#include "export_gltf.h"
#include "headless.h"
#include "image.h"
#include "panels.h"
#include "scene.h"
#include "state.h"
#include "window.h"

namespace mobb::app {

namespace {

using viewer::Scene;
using viewer::State;

float aspect(int w, int h) { return float(w) / float(std::max(h, 1)); }

/// The default scene: assets/scenes/default.json from the working folder, else from the source tree.
std::string default_scene() {
    std::string local = "assets/scenes/default.json";
    if (std::filesystem::exists(local)) return local;
    return std::string(MOBB_ASSETS_DIR) + "/scenes/default.json";
}

/// Puts each clip's path midpoint at the origin under its rotation, so crossing directions cross.
void centre_clips(State& s) {
    for (std::size_t k = 0; k < s.scene.clips.size(); ++k) {
        const Path& path = s.clips[k].tree->path();
        const Sample &a = path.samples.front(), &b = path.samples.back();
        Placement& p = s.places[k];
        const double mx = 0.5 * (a.x + b.x), my = 0.5 * (a.y + b.y);
        const Rigid2 turn = Rigid2::of({0, 0, p.theta, 0});
        p.x = -turn.apply_x(mx, my);
        p.y = -turn.apply_y(mx, my);
    }
    viewer::run_query(s);
}

/// `--step K` (negative: not given): a step of the query's trace. Throws InputError naming the option when
/// there is no trace or it has no step K.
void apply_step(State& s, int step, const std::string& command) {
    if (step < 0) return;
    const std::string option = command + ": --step " + std::to_string(step);
    if (!s.queried || s.trace.empty())
        throw InputError(option + ": no query trace to step through" +
                         (s.crowd ? " (open one with --choice and --candidate)" : " (the scene has no query)"));
    if (std::size_t(step) >= s.trace.size())
        throw InputError(option + ": the trace has " + std::to_string(s.trace.size()) + " steps (0 to " +
                         std::to_string(s.trace.size() - 1) + ")");
    s.scene.step = step;
}

/// Whether the command line names clip files (any format load_clip reads) rather than one scene (.json).
bool names_clip_files(const std::vector<std::string>& inputs) {
    return !inputs.empty() && !(inputs.size() == 1 && std::filesystem::path(inputs[0]).extension() == ".json");
}

/// The scene of clip files named on the command line, each loaded with `load`.
Scene scene_of_inputs(const std::vector<std::string>& files, const io::LoadOptionText& load) {
    std::vector<std::string> abs;
    abs.reserve(files.size());
    for (const std::string& f : files) abs.push_back(std::filesystem::absolute(f).string());
    Scene scene = viewer::scene_of_files(abs);
    for (auto& c : scene.clips) c.load = load;
    return scene;
}

/// Clip files' state as the viewer opens it: paths centred, the query's first step, everything framed.
void arrange_clip_files(State& s, float asp) {
    centre_clips(s);
    if (s.queried) s.scene.step = 0;
    viewer::frame_all(s, asp);
}

/// `render --colour-disks` / `--colour-boxes` (empty: the scene's); a box colouring shows the boxes.
void apply_colouring(State& s, const std::string& disks, const std::string& boxes) {
    try {
        if (!disks.empty()) s.scene.layers.disk_colour = render::parse_disk_colour(disks);
        if (!boxes.empty()) {
            s.scene.layers.box_colour = render::parse_box_colour(boxes);
            s.scene.layers.boxes = true;
        }
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("render: ") + e.what());
    }
}

/// A recorded crowd's state for `render --crowd` and `view --crowd`: the agent's choice points listed,
/// the cursor at `time` (negative: the middle of the run) with `window` seconds drawn either side
/// (negative: the crowd's default), the camera from the space-time side. Throws InputError naming
/// --agent or --time when the record has no such agent or ends before `time`.
State crowd_state(const std::string& record, float asp, int agent, double time, double window) {
    State s = viewer::load_crowd_state(record, asp, time, window);
    const auto& r = s.crowd->record();
    if (agent < 0 || std::size_t(agent) >= r.tracks.size())
        throw InputError("render: --agent " + std::to_string(agent) + ": the record has " +
                         std::to_string(r.tracks.size()) + " agents (0 to " + std::to_string(r.tracks.size() - 1) +
                         ")");
    const double end = double(r.frames) * r.dt;
    if (time > end) {
        std::ostringstream m;
        m << "render: --time " << time << ": the record ends at " << end << " s";
        throw InputError(m.str());
    }
    viewer::select_choice(s, agent, -1);
    s.scene.cursor = time >= 0 ? time : 0.5 * end;
    return s;
}

/// `render --crowd ... --choice C [--candidate K [--query J]]`: selects choice point C (the cursor at
/// its time unless --time was given) and opens query J (default 0) of its candidate K in the trace,
/// as the crowd panel does. Throws InputError with the reason when the record has no such query.
void open_crowd_query(State& s, int choice, int candidate, int query, bool keep_time) {
    const auto& r = s.crowd->record();
    if (choice < 0) {
        if (candidate >= 0 || query >= 0) throw InputError("render: --candidate and --query need --choice");
        return;
    }
    const std::size_t choices = s.crowd->reader->choice_count();
    if (std::size_t(choice) >= choices)
        throw InputError("render: --choice " + std::to_string(choice) + ": the record has " + std::to_string(choices) +
                         " choice points");
    viewer::select_choice(s, -1, choice);
    const crowd::ChoicePoint& c = s.crowd->selected;
    if (!keep_time) s.scene.cursor = double(c.frame) * r.dt;
    if (candidate < 0) {
        if (query >= 0) throw InputError("render: --query needs --candidate");
        return;
    }
    if (std::size_t(candidate) >= c.candidates.size())
        throw InputError("render: --candidate " + std::to_string(candidate) + ": choice point " +
                         std::to_string(choice) + " has " + std::to_string(c.candidates.size()) + " candidates");
    const std::size_t queries = c.candidates[std::size_t(candidate)].against.size();
    if (query >= 0 && std::size_t(query) >= queries)
        throw InputError("render: --query " + std::to_string(query) + ": candidate " + std::to_string(candidate) +
                         " of choice point " + std::to_string(choice) + " lists " + std::to_string(queries) +
                         " queries");
    std::string message;
    if (!viewer::open_candidate_query(s, candidate, std::max(query, 0), &message))
        throw InputError("render: --candidate " + std::to_string(candidate) + " --query " +
                         std::to_string(std::max(query, 0)) + ": " + message);
}

/// "CLIP:SAMPLE" -> pick: two integers in range of int around a colon, nothing else (not even spaces).
bool parse_pick(const std::string& text, viewer::Pick& pick) {
    const char* const last = text.data() + text.size();
    const auto [colon, clip_error] = std::from_chars(text.data(), last, pick.clip);
    if (clip_error != std::errc() || colon == last || *colon != ':') return false;
    const auto [end, sample_error] = std::from_chars(colon + 1, last, pick.sample);
    return sample_error == std::errc() && end == last;
}

/// `render --ui --pick CLIP:SAMPLE [--pick ..] --panel NAME ..`: the panels' state the image starts
/// from, as clicks and the View menu would leave it: the panels the state opens by default and those
/// named; `frame`: everything framed in the viewport the panels leave. Throws InputError naming a bad
/// pick or panel.
viewer::Ui ui_start(State& s, const std::vector<std::string>& picks, const std::vector<std::string>& panels,
                    bool frame) {
    viewer::Ui ui;
    ui.panels = viewer::default_panels(s);
    ui.request_frame_all = frame;
    for (const std::string& p : picks) {
        viewer::Pick pick;
        if (!parse_pick(p, pick) || pick.clip < 0 || pick.clip >= int(s.clips.size()) || pick.sample < 0 ||
            pick.sample >= int(s.clips[std::size_t(pick.clip)].tree->path().size()))
            throw InputError("render: --pick " + p + ": expected CLIP:SAMPLE naming a disk of the scene");
        viewer::click_disk(s, ui, pick);
    }
    for (const std::string& name : panels) {
        const auto& list = viewer::panel_list();
        const auto it = std::find_if(list.begin(), list.end(), [&](const auto& i) { return name == i.name; });
        if (it == list.end()) throw InputError("render: --panel " + name + ": no such panel");
        ui.panels.*it->open = true;
    }
    return ui;
}

// One line of `mobb render --bench`: what was drawn (the disk layer groups consecutive samples of crowds
// seen from afar, level of detail k), the draw calls and vertices of the last frame, and frames per second.
void print_bench(std::ostream& out, const std::string& what, const viewer::BenchResult& r, int w, int h) {
    out << "bench: " << what << ", " << r.disks.disks << " disks in " << r.disks.instances
        << " instances at LOD k=" << r.disks.k_min;
    if (r.disks.k_max != r.disks.k_min) out << ".." << r.disks.k_max;
    out << ", " << r.draws.calls << " draw calls, " << r.draws.vertices << " vertices, " << w << "x" << h << ", "
        << std::fixed << std::setprecision(2) << r.fps << " frames per second\n";
}

// What `mobb render` reads from its command line.
struct RenderArgs {
    std::string out, crowd, disk_colour, box_colour;
    std::vector<std::string> inputs, picks, panels;
    int width = 0, height = 0, step = -1, bench_frames = 10, agent = 0, choice = -1, candidate = -1, query = -1;
    double time = -1, window = -1, time_scale = 0;
    std::vector<double> region;  ///< x0 y0 x1 y1, metres
    bool ui = false, help = false, bench = false, top = false, no_msaa = false, bodies = false;
};

void add_render_options(CLI::App& cmd, RenderArgs& a) {
    cmd.add_option("SCENE_OR_FILES", a.inputs, "A scene (.json) or clip files: BVH, glTF, FBX, ...");
    cmd.add_option("--crowd", a.crowd, "Render a crowd record (mobb crowd --record) instead of a scene");
    cmd.add_flag("--bodies", a.bodies,
                 "Crowd agents as bodies, a capsule per bone, not lines (the scene's layers.bodies; Scene panel)");
    cmd.add_option("--time", a.time, "With --crowd: time cursor in seconds (default: the middle)")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--window", a.window,
                   "Seconds either side of the time cursor drawn, 0 for all time (default: the scene's; 5 for "
                   "crowds)")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--agent", a.agent, "With --crowd: agent listed in the crowd panel")->check(CLI::NonNegativeNumber);
    cmd.add_option("--choice", a.choice, "With --crowd: select this choice point (index in the record)")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--candidate", a.candidate, "With --choice: open a query of this candidate in the trace")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--query", a.query, "With --candidate: which of its queries, in the order run (default 0)")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--colour-disks", a.disk_colour,
                   "Disks coloured by clip (default), radius, speed, time or clearance, with a colour bar");
    cmd.add_option("--colour-boxes", a.box_colour,
                   "Boxes shown and coloured by level (default), tightness or tests (by the query), with a colour bar");
    cmd.add_flag("--top", a.top, "With --crowd: the top view (the panels' \"top\", the T key)");
    cmd.add_option("--region", a.region,
                   "With --crowd: X0 Y0 X1 Y1, the part of the world (metres) the camera frames over the time window")
        ->expected(4);
    cmd.add_option("--time-scale", a.time_scale, "Metres the up axis draws per second (default: the scene's)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--out", a.out, "PNG file to write");
    cmd.add_option("--width", a.width, "Image width (default: the scene's; 1280 with --bench)")
        ->check(CLI::Range(16, 8192));
    cmd.add_option("--height", a.height, "Image height (default: the scene's; 720 with --bench)")
        ->check(CLI::Range(16, 8192));
    cmd.add_option("--step", a.step, "Trace step to show (default: the scene's)")->check(CLI::NonNegativeNumber);
    cmd.add_flag("--ui", a.ui, "Also draw the ImGui panels");
    cmd.add_flag("--shortcuts", a.help, "With --ui: the Shortcuts window open too (F1 in the viewer)");
    cmd.add_option("--pick", a.picks, "With --ui: click disk CLIP:SAMPLE (twice: the Inspector's ruler)");
    cmd.add_option("--panel", a.panels, "With --ui: also open this panel (as in the View menu), e.g. Open");
    cmd.add_flag("--no-msaa", a.no_msaa,
                 "One sample per pixel instead of 4x multisampling: jagged edges, about 3x less fill work "
                 "(crowds of over 100,000 disks always)");
    cmd.add_flag("--bench", a.bench, "Print frames per second instead of writing an image");
    cmd.add_option("--bench-frames", a.bench_frames, "Frames timed by --bench")->check(CLI::Range(1, 100000));
}

// The usage errors the parser cannot see: options that do not go together. Prints one line and returns
// false on the first.
bool check_render_usage(const RenderArgs& a) {
    if (a.out.empty() && !a.bench) {
        std::cerr << "render: --out FILE.png is required (or --bench)\n";
        return false;
    }
    if (a.inputs.empty() == a.crowd.empty()) {
        std::cerr << "render: expected a SCENE, clip files or --crowd RECORD.json (one of them)\n";
        return false;
    }
    if (!a.ui && (!a.picks.empty() || !a.panels.empty() || a.help)) {
        std::cerr << "render: --pick, --panel and --shortcuts go with --ui\n";
        return false;
    }
    if (a.crowd.empty() && (a.choice >= 0 || a.candidate >= 0 || a.query >= 0 || a.time >= 0 || a.top)) {
        std::cerr << "render: --time, --top, --choice, --candidate and --query go with --crowd\n";
        return false;
    }
    if (!a.region.empty() && (a.crowd.empty() || a.region[0] >= a.region[2] || a.region[1] >= a.region[3])) {
        std::cerr << "render: --region X0 Y0 X1 Y1 goes with --crowd, with X0 < X1 and Y0 < Y1\n";
        return false;
    }
    return true;
}

// What the command line sets on any state it renders: trace step, colouring, time window, samples, bodies.
void apply_render_args(State& s, const RenderArgs& a) {
    apply_step(s, a.step, "render");
    apply_colouring(s, a.disk_colour, a.box_colour);
    if (a.window >= 0) s.scene.window = a.window;
    if (a.no_msaa) s.scene.multisample = false;
    if (a.bodies) s.scene.layers.bodies = true;
    if (a.time_scale > 0) s.scene.time_scale = a.time_scale;
}

// `render --crowd RECORD`: the record at the time cursor.
void render_crowd(const RenderArgs& a, std::ostream& out) {
    const int w = a.width ? a.width : 960, h = a.height ? a.height : 540;
    State s = crowd_state(a.crowd, aspect(w, h), a.agent, a.time, a.window);
    open_crowd_query(s, a.choice, a.candidate, a.query, a.time >= 0);
    apply_render_args(s, a);
    if (a.top) s.camera.top();
    if (a.top || a.time_scale > 0) viewer::frame_all(s, aspect(w, h));
    if (!a.region.empty()) viewer::frame_region(s, a.region[0], a.region[1], a.region[2], a.region[3], aspect(w, h));
    if (a.bench) {
        print_bench(out, "crowd", viewer::bench_headless(s, w, h, a.bench_frames), w, h);
        return;
    }
    const viewer::Ui start = ui_start(s, a.picks, a.panels, true);
    render::write_png(a.out, viewer::render_headless(s, {w, h, a.ui, a.help, &start}));
    out << a.out << "\n";
}

// `render SCENE` or `render FILES...`.
void render_scene(const RenderArgs& a, std::ostream& out) {
    const bool files = names_clip_files(a.inputs);
    Scene scene = files ? scene_of_inputs(a.inputs, {}) : viewer::load_scene(a.inputs[0]);
    const int w = a.width ? a.width : a.bench ? 1280 : scene.width;
    const int h = a.height ? a.height : a.bench ? 720 : scene.height;
    State s = viewer::load_state(scene, aspect(w, h));
    if (files) arrange_clip_files(s, aspect(w, h));
    apply_render_args(s, a);
    if (a.bench) {
        const viewer::BenchResult r = viewer::bench_headless(s, w, h, a.bench_frames);
        print_bench(out, std::to_string(s.clips.size()) + " clips", r, w, h);
        return;
    }
    const viewer::Ui start = ui_start(s, a.picks, a.panels, files || !scene.camera);
    render::write_png(a.out, viewer::render_headless(s, {w, h, a.ui, a.help, &start}));
    out << a.out << "\n";
}

void add_render(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("render", "Render a scene to PNG with no display (OSMesa, llvmpipe)");
    auto a = std::make_shared<RenderArgs>();
    add_render_options(*cmd, *a);
    cmd->callback([a, &exit_code] {
        if (!check_render_usage(*a)) {
            exit_code = kUsage;
            return;
        }
        exit_code =
            guarded([&](std::ostream& out) { a->crowd.empty() ? render_scene(*a, out) : render_crowd(*a, out); });
    });
}

struct ViewArgs {
    std::vector<std::string> inputs;
    io::LoadOptionText load;
    std::string screenshot, crowd, save_state;
    int frames = 0, width = 1280, height = 800;
    bool no_msaa = false;
    TreeArgs tree;
};

// Opens a window on the state, or renders it headless when there is no display (`what` names it; the
// window keeps its camera under `key` in the user's settings). `frame`: the state has no camera of its
// own, so everything is framed in the viewport the panels leave.
void show(State& s, const ViewArgs& a, const std::string& what, const std::string& key, bool frame, std::ostream& out) {
    if (a.no_msaa) s.scene.multisample = false;
    if (!render::display_available()) {
        const std::string png = a.screenshot.empty() ? "mobb-view.png" : a.screenshot;
        viewer::Ui start;
        start.panels = viewer::default_panels(s);
        start.request_frame_all = frame;
        render::write_png(png, viewer::render_headless(s, {a.width, a.height, true, false, &start}));
        std::cerr << "no display: rendered " << what << " headless to " << std::filesystem::absolute(png).string()
                  << "\n";
        return;
    }
    viewer::WindowOptions w;
    w.width = a.width;
    w.height = a.height;
    w.frames = a.frames;
    w.screenshot = a.screenshot;
    w.settings_key = key;
    w.frame_all = frame;
    viewer::run_window(s, w);
    if (!a.screenshot.empty()) out << a.screenshot << "\n";
    if (!a.save_state.empty()) {  // the scene as the window left it: clips, placements, step, camera
        viewer::sync_scene(s);
        viewer::save_scene(s.scene, a.save_state);
        out << a.save_state << "\n";
    }
}

void add_view(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("view", "Open the interactive viewer on a scene or on clip files");
    auto a = std::make_shared<ViewArgs>();
    cmd->add_option("SCENE_OR_FILES", a->inputs,
                    "A scene (.json) or clip files: BVH, glTF, FBX (default: assets/scenes/default.json)");
    // Not LoadArgs: here --frames is the number of frames to show, not the clips' frame range.
    cmd->add_option("--up", a->load.up, "Up axis of BVH files: y or z")->check(CLI::IsMember({"y", "z"}));
    cmd->add_option("--scale", a->load.scale, "Metres per file unit, or auto");
    cmd->add_option("--fps", a->load.fps, "Resample clip files to F samples per second")->check(CLI::PositiveNumber);
    a->tree.add_to(*cmd, false);
    cmd->add_option("--frames", a->frames, "Close after N frames (with --screenshot: smoke tests)")
        ->check(CLI::Range(1, 1 << 30));
    cmd->add_option("--screenshot", a->screenshot, "Save the last frame to this PNG");
    cmd->add_option("--save-state", a->save_state,
                    "When the window closes, save the scene as it was left (clips, placements, step, camera)");
    cmd->add_option("--crowd", a->crowd, "Show a crowd record (mobb crowd --record) instead of a scene");
    cmd->add_option("--width", a->width, "Window width")->check(CLI::Range(16, 8192));
    cmd->add_option("--height", a->height, "Window height")->check(CLI::Range(16, 8192));
    cmd->add_flag("--no-msaa", a->no_msaa, "Start without multisampling (View > Smooth edges): faster, jagged edges");
    cmd->callback([a, cmd, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            if (!a->crowd.empty()) {
                if (!a->inputs.empty()) throw InputError("view: --crowd takes no scene or clip files");
                if (!a->save_state.empty()) throw InputError("view: --save-state saves scenes, not crowds");
                State s = crowd_state(a->crowd, aspect(a->width, a->height), 0, -1, -1);
                show(s, *a, a->crowd, "crowd " + std::filesystem::absolute(a->crowd).string(), true, out);
                return;
            }
            const bool files = names_clip_files(a->inputs);
            std::string scene_file, key;
            Scene scene;
            if (files) {
                scene = scene_of_inputs(a->inputs, a->load);
                key = "files";
                for (const auto& c : scene.clips) key += " " + c.file;
            } else {
                scene_file = a->inputs.empty() ? default_scene() : a->inputs[0];
                scene = viewer::load_scene(scene_file);
                key = "scene " + std::filesystem::absolute(scene_file).string();
            }
            if (cmd->count("--tree") || cmd->count("--nmin") || cmd->count("--fit")) scene.tree = a->tree.options();
            State s = viewer::load_state(scene, aspect(a->width, a->height));
            if (files) arrange_clip_files(s, aspect(a->width, a->height));
            show(s, *a, scene_file.empty() ? "the clips" : scene_file, key, files || !scene.camera, out);
        });
    });
}

void add_export(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("export-gltf", "Write a scene's visible disk stacks and boxes as a glTF binary");
    auto scene_file = std::make_shared<std::string>();
    auto out_file = std::make_shared<std::string>();
    auto step = std::make_shared<int>(-1);
    cmd->add_option("SCENE", *scene_file, "Scene file (JSON)")->required();
    cmd->add_option("--out", *out_file, "GLB file to write")->required();
    cmd->add_option("--step", *step, "Trace step to include (default: the scene's)")->check(CLI::NonNegativeNumber);
    cmd->callback([=, &exit_code] {
        exit_code = guarded([&](std::ostream& out) {
            const Scene scene = viewer::load_scene(*scene_file);
            State s = viewer::load_state(scene, aspect(scene.width, scene.height));
            apply_step(s, *step, "export-gltf");
            const viewer::GltfSummary g = viewer::export_gltf(s, *out_file);
            out << *out_file << ": " << g.meshes << " meshes, " << g.nodes << " nodes, " << g.materials
                << " materials\n";
        });
    });
}

}  // namespace

void add_view_commands(CLI::App& app, int& exit_code) {
    add_view(app, exit_code);
    add_render(app, exit_code);
    add_export(app, exit_code);
}

}  // namespace mobb::app
