#include "window.h"

#include <filesystem>
#include <stdexcept>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>

#include "context_glfw.h"
#include "crowd_view.h"
#include "gl.h"
#include "image.h"
#include "layout.h"
#include "panels.h"
#include "picking.h"
#include "renderer.h"
#include "shortcuts.h"
#include "view_settings.h"

namespace mobb::viewer {

namespace {

enum class Drag { None, Orbit, Pan, Move };

/// Mouse gestures over the 3D view: orbit, pan, zoom, click to pick, ctrl+drag to move a clip.
struct Input {
    Drag drag = Drag::None;
    float travel = 0;        ///< pixels moved since the press (a click moves less than 4)
    int clip = -1;           ///< clip being moved
    double height = 0;       ///< GL height of the plane a clip is dragged on
    glm::dvec2 anchor{0.0};  ///< ground point under the mouse at the last move
};

/// The ray under the mouse, through the viewport the columns leave.
render::Ray mouse_ray(const State& s, const Ui& ui, const ImGuiIO& io) {
    const Rect v = viewport(s, ui);
    return s.camera.ray(io.MousePos.x - v.x, io.MousePos.y - v.y, v.width, v.height);
}

/// A click in the 3D view: a disk picks it; away from disks, a box of the query selects its events.
void click(State& s, Ui& ui, const ImGuiIO& io) {
    const render::Ray ray = mouse_ray(s, ui, io);
    double disk = 0;
    const Pick p = pick_disk(s, ray, &disk);
    if (p.clip >= 0) return click_disk(s, ui, p);
    const BoxPick b = pick_box(s, ray);
    if (b.node >= 0) click_box(s, ui, b.clip, b.node);
}

void mouse(State& s, Ui& ui, Input& in) {
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 d = io.MouseDelta;
    in.travel += std::abs(d.x) + std::abs(d.y);  // before a press resets it: moving onto a disk is not a drag
    const Rect view = viewport(s, ui);
    if (!io.WantCaptureMouse && view.contains(io.MousePos.x, io.MousePos.y)) {
        if (io.MouseWheel != 0.0f) s.camera.zoom(io.MouseWheel);
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            in.travel = 0;
            in.drag = io.KeyShift ? Drag::Pan : io.KeyCtrl ? Drag::Move : Drag::Orbit;
            if (in.drag == Drag::Move) {
                const render::Ray ray = mouse_ray(s, ui, io);
                const Pick p = pick_disk(s, ray);
                in.clip = p.clip;
                if (p.clip < 0) {
                    in.drag = Drag::None;
                } else {
                    const Path& path = s.clips[std::size_t(p.clip)].tree->path();
                    in.height = sample_time(s.places[std::size_t(p.clip)], path.dt, p.sample) * s.scene.time_scale;
                    in.anchor = ground_point(ray, in.height).value_or(glm::dvec2(0.0));
                }
            }
        }
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) in.drag = Drag::Pan;
    }
    const bool held = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Middle);
    if (held && (d.x != 0 || d.y != 0)) {
        if (in.drag == Drag::Orbit) s.camera.orbit(d.x * 0.3f, d.y * 0.3f);
        if (in.drag == Drag::Pan) s.camera.pan(d.x, d.y, view.height);
        if (in.drag == Drag::Move) {
            if (const auto g = ground_point(mouse_ray(s, ui, io), in.height)) {
                Placement& p = s.places[std::size_t(in.clip)];
                p.x += g->x - in.anchor.x;
                p.y += g->y - in.anchor.y;
                in.anchor = *g;
                run_query(s);
            }
        }
    }
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && in.drag == Drag::Orbit && in.travel < 4) click(s, ui, io);
    if (!held) in.drag = Drag::None;
}

/// What GLFW's callbacks collected since the last frame (the window's user pointer). Keys come from
/// the callback rather than ImGui's per-frame key state so that a press released within one slow
/// frame still counts, and each press counts once.
struct Events {
    struct Key {
        int key;
        bool shift, repeat;
    };
    std::vector<Key> keys;
    std::vector<std::string> dropped;
};

void on_key(GLFWwindow* window, int key, int, int action, int mods) {
    auto* events = static_cast<Events*>(glfwGetWindowUserPointer(window));
    if (events && action != GLFW_RELEASE)
        events->keys.push_back({key, (mods & GLFW_MOD_SHIFT) != 0, action == GLFW_REPEAT});
}

/// GLFW's drop callback: the paths are opened on the next frame.
void on_drop(GLFWwindow* window, int count, const char** paths) {
    auto* events = static_cast<Events*>(glfwGetWindowUserPointer(window));
    for (int k = 0; events && k < count; ++k) events->dropped.emplace_back(paths[k]);
}

void keyboard(State& s, Ui& ui, Events& events) {
    const bool typing = ImGui::GetIO().WantCaptureKeyboard;
    for (const Events::Key& k : events.keys)
        if (const Shortcut* sc = typing ? nullptr : find_shortcut(k.key, k.shift, k.repeat))
            run_command(sc->command, s, ui);
    events.keys.clear();
    ui.dropped.insert(ui.dropped.end(), events.dropped.begin(), events.dropped.end());
    events.dropped.clear();
}

/// ImGui's ini in the user's config folder, with the user's panel choices, the columns and the camera of
/// `key` in it; the panels open are the defaults for the state with the choices over them.
/// Loaded now (not at the first frame) so the camera is in place before anything is drawn.
/// A crowd read in windows: the frames around the cursor, read as it moves; a file that cannot be read
/// stops the playing and says why in the status line.
void sync_window(State& s, Ui& ui) {
    try {
        sync_crowd(s);
    } catch (const std::runtime_error& e) {
        ui.status = e.what();
        s.crowd->playing = false;
    }
}

void load_settings(State& s, Ui& ui, ViewSettings& settings, const std::string& file, const std::string& key) {
    add_settings_handler(settings);
    ui.panels = default_panels(s);
    if (file.empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(file).parent_path(), ec);
    ImGui::GetIO().IniFilename = file.c_str();
    if (std::filesystem::exists(file)) ImGui::LoadIniSettingsFromDisk(file.c_str());
    ui.panel_choices = settings.panel_choices;
    ui.panels = default_panels(s, ui.panel_choices);
    ui.columns = settings.columns;
    if (const auto c = settings.cameras.find(key); !key.empty() && c != settings.cameras.end()) {
        s.camera = c->second;
        ui.request_frame_all = false;
    }
}

/// Copies what changed into the settings and tells ImGui to write its ini (at its own pace).
void keep_settings(const State& s, const Ui& ui, ViewSettings& settings, const std::string& key) {
    const Columns& c = settings.columns;
    bool changed = settings.panel_choices != ui.panel_choices || c.left != ui.columns.left ||
                   c.right != ui.columns.right || c.left_collapsed != ui.columns.left_collapsed ||
                   c.right_collapsed != ui.columns.right_collapsed || c.bottom_collapsed != ui.columns.bottom_collapsed;
    settings.panel_choices = ui.panel_choices;
    settings.columns = ui.columns;
    if (!key.empty() && camera_line(settings.cameras[key]) != camera_line(s.camera)) {
        settings.cameras[key] = s.camera;
        changed = true;
    }
    if (changed) ImGui::MarkIniSettingsDirty();
}

// The window's title once its first frames have placed the panels in their columns: "mobb view - NAME"
// (the scene's file name). The window tests wait for it before they click (tests/app/x11_window.sh).
constexpr int kTitledFrame = 10;  // ImGui sizes and places windows over its first frames

std::string titled(const WindowOptions& options) {
    const std::string name = std::filesystem::path(options.scene_file).filename().string();
    return "mobb view - " + (name.empty() ? std::string("untitled") : name);
}

}  // namespace

void run_window(State& s, const WindowOptions& options) {
    render::GlfwWindow window("mobb view", options.width, options.height);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // never imgui.ini in the working folder
    apply_style();
    Events events;
    glfwSetWindowUserPointer(window.handle(), &events);
    glfwSetKeyCallback(window.handle(), on_key);  // before ImGui's, which calls it after its own
    glfwSetDropCallback(window.handle(), on_drop);
    ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    {
        render::Renderer renderer;
        Ui ui;
        Input input;
        if (!options.scene_file.empty()) ui.save_path = options.scene_file;
        const std::string ini = settings_file();
        ui.request_frame_all = options.frame_all;
        ViewSettings settings;
        load_settings(s, ui, settings, ini, options.settings_key);
        for (int frame = 1;; ++frame) {
            glfwPollEvents();
            // The last frame: closed, quit (Q), or the frame count reached; drawn, then saved if asked.
            const bool last =
                window.should_close() || ui.request_quit || (options.frames > 0 && frame >= options.frames);
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            const glm::ivec2 size = window.window_size(), fb = window.framebuffer_size();
            ui.window_size = size;
            mouse(s, ui, input);
            keyboard(s, ui, events);
            update_playback(s, ui, ImGui::GetIO().DeltaTime);
            draw_panels(s, ui);
            apply_requests(s, ui);
            sync_window(s, ui);
            keep_settings(s, ui, settings, options.settings_key);
            ImGui::Render();
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            renderer.draw(frame_of(s), s.camera, gl_viewport(viewport(s, ui), size, fb));
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            if (last) {
                if (!options.screenshot.empty()) {
                    glFinish();
                    glReadBuffer(GL_BACK);
                    render::write_png(options.screenshot, render::read_pixels(fb.x, fb.y));
                }
                break;
            }
            window.swap();
            if (frame == kTitledFrame) glfwSetWindowTitle(window.handle(), titled(options).c_str());
        }
        if (!ini.empty()) ImGui::SaveIniSettingsToDisk(ini.c_str());
        ImGui::GetIO().IniFilename = nullptr;  // `ini` goes out of scope before DestroyContext
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwSetWindowUserPointer(window.handle(), nullptr);
}

}  // namespace mobb::viewer
