#include "renderer.h"

#include <algorithm>

#include "box_layer.h"
#include "colour_bar_layer.h"
#include "cursor_layer.h"
#include "disk_layer.h"
#include "grid_layer.h"
#include "prism_layer.h"
#include "shader.h"
#include "text_layer.h"
#include "trace_layer.h"

namespace mobb::render {

Bounds scene_bounds(const Frame& frame) {
    Bounds b;
    for (const ClipView& clip : frame.clips) {
        if (!clip.visible) continue;
        const Path& path = clip.tree->path();
        const Rigid2 m = Rigid2::of(clip.place);
        for (const Sample& s : path.samples) {
            const double x = m.apply_x(s.x, s.y), y = m.apply_y(s.x, s.y);
            b.add({x - s.r, y - s.r, clip.place.t0});
            b.add({x + s.r, y + s.r, clip.place.t0});
        }
        if (!path.samples.empty()) b.add({b.lo.x, b.lo.y, clip.place.t0 + path.duration()});
    }
    for (const Prism& p : frame.prisms) {
        if (p.on_top) continue;
        for (const auto& g : p.ground) {
            b.add({g[0], g[1], p.t0});
            b.add({g[0], g[1], p.t1});
        }
    }
    if (!frame.extent.empty) {
        b.add(frame.extent.lo);
        b.add(frame.extent.hi);
    }
    return b;
}

bool multisampled(const Frame& frame) {
    std::size_t disks = 0;
    for (const ClipView& clip : frame.clips) disks += clip.tree->path().size();
    return frame.multisample && disks <= kMultisampleUpTo;
}

void gl_bounds(const Bounds& bounds, double time_scale, glm::vec3& lo, glm::vec3& hi) {
    const glm::vec3 a = to_gl(bounds.lo.x, bounds.lo.y, bounds.lo.z, time_scale);
    const glm::vec3 b = to_gl(bounds.hi.x, bounds.hi.y, bounds.hi.z, time_scale);
    lo = glm::min(a, b);
    hi = glm::max(a, b);
}

struct Renderer::Layers {
    Program color{"color.vert", "color.frag"};
    Program disk{"disk.vert", "disk.frag"};
    Program tube{"tube.vert", "disk.frag"};
    GridLayer grid;
    DiskLayer disks;
    BoxLayer boxes;
    PrismLayer prisms;
    CursorLayer cursor;
    TraceLayer trace;
    TextLayer text;
    ColourBarLayer colour_bars;
};

Renderer::Renderer() : layers_(std::make_unique<Layers>()) {}
Renderer::~Renderer() = default;

const DiskStats& Renderer::disk_stats() const { return layers_->disks.stats(); }

const std::vector<DrawnLabel>& Renderer::labels() const { return layers_->text.drawn(); }

void Renderer::draw(const Frame& frame, const Camera& camera, int width, int height) {
    draw(frame, camera, Viewport{0, 0, width, height});
}

void Renderer::draw(const Frame& frame, const Camera& camera, const Viewport& viewport) {
    const int width = std::max(viewport.width, 1), height = std::max(viewport.height, 1);
    Layers& l = *layers_;
    reset_draw_counts();
    if (frame.revision != revision_) {
        l.disks.rebuild(frame);
        bounds_ = scene_bounds(frame);
        revision_ = frame.revision;
    }
    // On a multisampled framebuffer (the window's) this still writes every sample: headless targets
    // are made single-sampled instead (multisampled()).
    if (multisampled(frame))
        glEnable(GL_MULTISAMPLE);
    else
        glDisable(GL_MULTISAMPLE);
    DrawContext ctx;
    ctx.view_proj = camera.projection(float(width) / float(height)) * camera.view();
    ctx.width = width;
    ctx.height = height;
    ctx.color = &l.color;
    ctx.disk = &l.disk;
    ctx.tube = &l.tube;
    ctx.bounds = bounds_;

    glViewport(viewport.x, viewport.y, width, height);
    glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);

    glEnable(GL_CLIP_DISTANCE0);
    glEnable(GL_CLIP_DISTANCE1);
    // What lies in space-time is clipped to the time window; the grid, the cursor and text are not.
    DrawContext window = ctx;
    if (frame.window > 0) {
        window.clip_lo = float((frame.cursor - frame.window) * frame.time_scale);
        window.clip_hi = float((frame.cursor + frame.window) * frame.time_scale);
    }

    // Opaque pass.
    l.grid.draw(frame, ctx, l.text);
    l.disks.draw(frame, window, false);
    l.boxes.draw(frame, window, false);
    l.prisms.draw(frame, window, false);
    l.cursor.draw(frame, ctx, false, l.text);
    l.trace.draw(frame, window, false);

    // Translucent pass: blended, tested against the opaque depth but not writing it.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    l.disks.draw(frame, window, true);
    l.boxes.draw(frame, window, true);
    l.prisms.draw(frame, window, true);
    l.trace.draw(frame, window, true);
    l.cursor.draw(frame, ctx, true, l.text);

    // Marks that must stay visible through the translucent layers.
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    l.trace.draw_hit(frame, window, l.disks);

    // Labels, contacts and posed skeletons (crowd agents) on top.
    glDisable(GL_DEPTH_TEST);
    l.prisms.draw_on_top(frame, ctx);
    l.cursor.draw_posed(frame, ctx);
    l.colour_bars.draw(frame, ctx, l.text);
    l.text.draw(ctx);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    counts_ = render::draw_counts();
}

}  // namespace mobb::render
