#include "window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "context_glfw.h"
#include "gl.h"
#include "image.h"
#include "panels.h"
#include "picking.h"
#include "renderer.h"
#include "shortcuts.h"

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

render::Ray mouse_ray(const State& s, const ImGuiIO& io) {
    return s.camera.ray(io.MousePos.x, io.MousePos.y, io.DisplaySize.x, io.DisplaySize.y);
}

void mouse(State& s, Ui& ui, Input& in) {
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 d = io.MouseDelta;
    in.travel += std::abs(d.x) + std::abs(d.y);  // before a press resets it: moving onto a disk is not a drag
    if (!io.WantCaptureMouse) {
        if (io.MouseWheel != 0.0f) s.camera.zoom(io.MouseWheel);
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            in.travel = 0;
            in.drag = io.KeyShift ? Drag::Pan : io.KeyCtrl ? Drag::Move : Drag::Orbit;
            if (in.drag == Drag::Move) {
                const render::Ray ray = mouse_ray(s, io);
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
        if (in.drag == Drag::Pan) s.camera.pan(d.x, d.y, io.DisplaySize.y);
        if (in.drag == Drag::Move) {
            if (const auto g = ground_point(mouse_ray(s, io), in.height)) {
                Placement& p = s.places[std::size_t(in.clip)];
                p.x += g->x - in.anchor.x;
                p.y += g->y - in.anchor.y;
                in.anchor = *g;
                run_query(s);
            }
        }
    }
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && in.drag == Drag::Orbit && in.travel < 4)
        ui.pick = pick_disk(s, mouse_ray(s, io));
    if (!held) in.drag = Drag::None;
}

void keyboard(State& s, Ui& ui) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureKeyboard) return;
    for (const Shortcut& k : shortcuts())
        if (k.shift == io.KeyShift && ImGui::IsKeyPressed(k.key, k.repeat)) run_command(k.command, s, ui);
}

void apply_requests(State& s, Ui& ui, float aspect) {
    if (ui.request_view == 1) s.camera.top();
    if (ui.request_view == 2) s.camera.side();
    if (ui.request_view != 0 || ui.request_frame_all) frame_all(s, aspect);
    ui.request_view = 0;
    ui.request_frame_all = false;
}

}  // namespace

void run_window(State& s, const WindowOptions& options) {
    render::GlfwWindow window("mobb view", options.width, options.height);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // layouts come from the code, not from a file in the working folder
    apply_style();
    ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    {
        render::Renderer renderer;
        Ui ui;
        Input input;
        if (!options.scene_file.empty()) ui.save_path = options.scene_file;
        for (int frame = 1; !window.should_close(); ++frame) {
            glfwPollEvents();
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            const glm::ivec2 size = window.window_size(), fb = window.framebuffer_size();
            ui.window_size = size;
            mouse(s, ui, input);
            keyboard(s, ui);
            update_playback(s, ui, ImGui::GetIO().DeltaTime);
            draw_panels(s, ui);
            apply_requests(s, ui, float(size.x) / float(std::max(size.y, 1)));
            ImGui::Render();
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            renderer.draw(frame_of(s, kRightPanels * float(fb.x) / float(std::max(size.x, 1))), s.camera, fb.x, fb.y);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            if (options.frames > 0 && frame >= options.frames) {
                if (!options.screenshot.empty()) {
                    glFinish();
                    glReadBuffer(GL_BACK);
                    render::write_png(options.screenshot, render::read_pixels(fb.x, fb.y));
                }
                break;
            }
            window.swap();
        }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

}  // namespace mobb::viewer
