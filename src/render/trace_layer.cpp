#include "trace_layer.h"

#include <algorithm>

#include "box_layer.h"

namespace mobb::render {

const TraceEvent* current_event(const Frame& frame) {
    const TraceView& tv = frame.trace;
    if (!frame.layers.trace || !tv.events || tv.step < 0 || tv.step >= int(tv.events->size())) return nullptr;
    if (tv.a < 0 || tv.b < 0 || tv.a >= int(frame.clips.size()) || tv.b >= int(frame.clips.size())) return nullptr;
    return &(*tv.events)[std::size_t(tv.step)];
}

void TraceLayer::draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass) {
    const TraceEvent* ev = current_event(frame);
    if (!ev) return;
    ctx.use(*ctx.color);
    if (translucent_pass) return faces_.draw();
    const glm::vec3 color = outcome_color(ev->outcome);
    edges_.clear();
    faces_.clear();
    auto add = [&](const ClipView& clip, std::int32_t node) {
        if (node < 0 || node >= std::int32_t(clip.tree->nodes().size())) return;
        const Obb3 box =
            transformed(clip.tree->box3(clip.tree->nodes()[std::size_t(node)]), SpaceTimeRigid::of(clip.place));
        add_box(box, frame.time_scale, glm::vec4(color, 1.0f), edges_, glm::vec4(color, 0.12f), &faces_);
    };
    add(frame.clips[std::size_t(frame.trace.a)], ev->node_a);
    add(frame.clips[std::size_t(frame.trace.b)], ev->node_b);
    glLineWidth(3.0f);
    edges_.draw();
    glLineWidth(1.0f);
}

void TraceLayer::draw_hit(const Frame& frame, const DrawContext& ctx, DiskLayer& disks) {
    const TraceEvent* ev = current_event(frame);
    if (!ev || ev->outcome != TraceOutcome::Hit || ev->sample_a < 0 || ev->sample_b < 0) return;
    const glm::vec4 color(outcome_color(ev->outcome), 1.0f);
    auto disk = [&](const ClipView& clip, std::int32_t i) {
        const Path& path = clip.tree->path();
        const Sample& s = path.samples[std::size_t(i)];
        const Rigid2 m = Rigid2::of(clip.place);
        return DiskInstance(float(m.apply_x(s.x, s.y)), float(m.apply_y(s.x, s.y)),
                            float(sample_time(clip.place, path.dt, i)), float(s.r));
    };
    const ClipView& a = frame.clips[std::size_t(frame.trace.a)];
    const ClipView& b = frame.clips[std::size_t(frame.trace.b)];
    const DiskInstance da = disk(a, ev->sample_a), db = disk(b, ev->sample_b);
    // A sample lasts 1/60 s: thicken the marks so the pair reads at any zoom.
    disks.draw_marked(ctx, {da}, std::max(a.tree->path().dt, 0.04), frame.time_scale, color, 1.06f);
    disks.draw_marked(ctx, {db}, std::max(b.tree->path().dt, 0.04), frame.time_scale, color, 1.06f);
}

}  // namespace mobb::render
