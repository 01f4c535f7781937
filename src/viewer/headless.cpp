#include "headless.h"

#include "crowd_view.h"

#include <chrono>

#include <imgui.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>

#include "context_osmesa.h"
#include "layout.h"
#include "panels.h"
#include "renderer.h"
#include "target.h"

namespace mobb::viewer {

namespace {

/// Windows whose text is cut: content wider than the window (tables and lists that scroll sideways
/// excepted), a panel taller than its window (child lists may scroll), or a panel past the image edge.
std::vector<std::string> cut_windows(const ImVec2& display) {
    std::vector<std::string> out;
    for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
        const ImGuiWindowFlags skip = ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup | ImGuiWindowFlags_MenuBar;
        if (!w->WasActive || w->Hidden || (w->Flags & skip)) continue;  // the menu bar fits by construction
        char line[256];
        const bool child = (w->Flags & ImGuiWindowFlags_ChildWindow) != 0;
        const float wide = w->ContentSizeIdeal.x - w->ContentRegionRect.GetWidth();
        if (wide > 0.5f && !(w->Flags & ImGuiWindowFlags_HorizontalScrollbar)) {
            std::snprintf(line, sizeof line, "%s: %.0f px too narrow", w->Name, double(wide));
            out.emplace_back(line);
        }
        if (child) continue;
        if (w->ScrollMax.y > 0.5f) {
            std::snprintf(line, sizeof line, "%s: %.0f px too short", w->Name, double(w->ScrollMax.y));
            out.emplace_back(line);
        }
        if (w->Pos.x < -0.5f || w->Pos.y < -0.5f || w->Pos.x + w->Size.x > display.x + 0.5f ||
            w->Pos.y + w->Size.y > display.y + 0.5f) {
            std::snprintf(line, sizeof line, "%s: reaches past the image", w->Name);
            out.emplace_back(line);
        }
    }
    return out;
}

/// The windows drawn: panels and other windows, the menu bar, tooltips and popups left out.
std::vector<ImageRect> drawn_windows() {
    std::vector<ImageRect> out;
    for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
        const ImGuiWindowFlags skip =
            ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup | ImGuiWindowFlags_MenuBar | ImGuiWindowFlags_ChildWindow;
        if (w->WasActive && !w->Hidden && !(w->Flags & skip))
            out.push_back({w->Name, {w->Pos.x, w->Pos.y, w->Size.x, w->Size.y}});
    }
    return out;
}

/// The renderer's labels in image pixels: its boxes are in the viewport's, from its top-left corner.
std::vector<ImageRect> image_labels(const render::Renderer& renderer, const render::Viewport& v, int image_height) {
    std::vector<ImageRect> out;
    const float left = float(v.x), top = float(image_height - v.y - v.height);
    for (const render::DrawnLabel& l : renderer.labels())
        out.push_back({l.text, {left + l.box.x0, top + l.box.y0, l.box.x1 - l.box.x0, l.box.y1 - l.box.y0}});
    return out;
}

/// The panels laid out, the scene drawn in the viewport they leave (camera requests applied, as in the
/// window), then the panels over it, without any window: ImGui's OpenGL3 backend works in any context
/// once the display size is set by hand.
void draw_with_ui(State& state, render::Renderer& renderer, const HeadlessOptions& o) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini: images must not depend on earlier sessions
    apply_style();
    io.DisplaySize = ImVec2(float(o.width), float(o.height));
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_Init("#version 330 core");
    Ui ui;
    if (o.start)
        ui = *o.start;
    else
        ui.panels = default_panels(state);
    ui.window_size = {o.width, o.height};
    ui.show_help = ui.show_help || o.help;
    // Four frames: the first measures the menu bar and the panels' content, the second places the
    // panels in their columns by it, the next settle scroll limits, the last draws. Camera requests wait
    // for the last, when the viewport has its final size.
    const bool frame_all = ui.request_frame_all;
    const ViewPreset preset = ui.request_view;
    ui.request_frame_all = false;
    ui.request_view = ViewPreset::None;
    for (int pass = 0; pass < 4; ++pass) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        draw_panels(state, ui);
        if (pass == 3) ui.request_frame_all = frame_all, ui.request_view = preset;
        apply_requests(state, ui);
        ImGui::Render();
    }
    if (o.cut) *o.cut = cut_windows(io.DisplaySize);
    if (o.windows) *o.windows = drawn_windows();
    const glm::ivec2 size(o.width, o.height);
    const render::Viewport view = gl_viewport(viewport(state, ui), size, size);
    renderer.draw(frame_of(state), state.camera, view);
    if (o.labels) *o.labels = image_labels(renderer, view, o.height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

/// 4 samples per pixel, or 1 when the frame is not multisampled (a quarter of the fill's memory work).
int target_samples(const render::Frame& frame) { return render::multisampled(frame) ? 4 : 0; }

}  // namespace

render::Image render_headless(State& state, const HeadlessOptions& options) {
    sync_crowd(state);  // a crowd read in windows: the frames around the cursor
    render::OsMesaContext context(options.width, options.height);
    render::Target target(options.width, options.height, target_samples(frame_of(state)));
    render::Renderer renderer;
    target.bind();
    if (options.ui)
        draw_with_ui(state, renderer, options);
    else
        renderer.draw(frame_of(state), state.camera, options.width, options.height);
    if (options.labels && !options.ui)
        *options.labels = image_labels(renderer, {0, 0, options.width, options.height}, options.height);
    return target.read();
}

BenchResult bench_headless(State& state, int width, int height, int frames) {
    sync_crowd(state);
    render::OsMesaContext context(width, height);
    const render::Frame frame = frame_of(state);
    render::Target target(width, height, target_samples(frame));
    render::Renderer renderer;
    target.bind();
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
    return {double(frames) / seconds, renderer.disk_stats(), renderer.draw_counts()};
}

}  // namespace mobb::viewer
