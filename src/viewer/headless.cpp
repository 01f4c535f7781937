#include "headless.h"

#include <chrono>

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "context_osmesa.h"
#include "panels.h"
#include "renderer.h"
#include "target.h"

namespace mobb::viewer {

namespace {

/// The panels drawn into the current framebuffer without any window: ImGui's OpenGL3 backend works
/// in any context once the display size is set by hand.
void draw_ui(State& state, int width, int height, bool help) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini: images must not depend on earlier sessions
    apply_style();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_Init("#version 330 core");
    Ui ui;
    ui.window_size = {width, height};
    ui.show_help = help;
    // Two frames: the first lays windows out (auto-sized ones measure themselves), the second draws.
    for (int pass = 0; pass < 2; ++pass) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        draw_panels(state, ui);
        ImGui::Render();
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

}  // namespace

render::Image render_headless(State& state, const HeadlessOptions& options) {
    render::OsMesaContext context(options.width, options.height);
    render::Target target(options.width, options.height);
    render::Renderer renderer;
    target.bind();
    renderer.draw(frame_of(state, options.ui ? kRightPanels : 0.0f), state.camera, options.width, options.height);
    if (options.ui) draw_ui(state, options.width, options.height, options.help);
    return target.read();
}

double bench_headless(State& state, int width, int height, int frames, render::DiskStats* disks) {
    render::OsMesaContext context(width, height);
    render::Target target(width, height);
    render::Renderer renderer;
    target.bind();
    const render::Frame frame = frame_of(state);
    render::Camera camera = state.camera;
    for (int k = 0; k < 2; ++k) renderer.draw(frame, camera, width, height);  // uploads, shader compiles
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < frames; ++k) {
        camera.orbit(1.0f, 0.0f);  // a moving camera, as when the user orbits
        renderer.draw(frame, camera, width, height);
        glFinish();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (disks) *disks = renderer.disk_stats();
    return double(frames) / seconds;
}

}  // namespace mobb::viewer
