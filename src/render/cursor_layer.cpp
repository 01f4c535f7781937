#include "cursor_layer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "mobb/io/capsule.h"

namespace mobb::render {

int frame_at(const ClipView& clip, double t) {
    if (!clip.animation || clip.animation->frames() == 0) return -1;
    const double local = (t - clip.place.t0) / clip.animation->dt;
    const double f = std::floor(local + 1e-9);
    return f >= 0 && f < clip.animation->frames() ? int(f) : -1;
}

void CursorLayer::skeletons(const Frame& frame) {
    if (revision_ != frame.revision) {
        // Some files hang the skeleton below the root: stand each one on its lowest joint instead.
        floor_.assign(frame.clips.size(), 0.0);
        for (std::size_t c = 0; c < frame.clips.size(); ++c) {
            const io::Animation* anim = frame.clips[c].animation;
            if (!anim || anim->positions.empty()) continue;
            double lowest = 1e300;
            for (const glm::dvec3& p : anim->positions)
                lowest = std::min(lowest, io::to_ground(p, frame.clips[c].up).z);
            floor_[c] = lowest;
        }
        revision_ = frame.revision;
    }
    for (std::size_t c = 0; c < frame.clips.size(); ++c) {
        const ClipView& clip = frame.clips[c];
        const int f = clip.visible ? frame_at(clip, frame.cursor) : -1;
        if (f >= 0) skeleton(lines_, *clip.animation, clip.up, f, Rigid2::of(clip.place), floor_[c], frame, clip.color);
    }
}

void CursorLayer::draw_posed(const Frame& frame, const DrawContext& ctx) {
    if (!frame.layers.skeletons || frame.posed.empty()) return;
    posed_.clear();
    bodies_.clear();
    for (const PosedSkeleton& p : frame.posed)
        if (!p.joints.empty() && p.parents && p.parents->size() == p.joints.size())
            frame.layers.bodies ? body(bodies_, p, frame) : joints(posed_, p, frame);
        else if (p.animation && p.frame >= 0 && p.frame < p.animation->frames())
            skeleton(posed_, *p.animation, p.up, p.frame, Rigid2::of(p.place), p.floor, frame, p.color);
    ctx.use(*ctx.color);
    if (!bodies_.empty()) {
        // Over the stacks like the lines, but solid among themselves: a fresh depth buffer for the bodies.
        glClear(GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        bodies_.draw();
        glDisable(GL_DEPTH_TEST);
    }
    glLineWidth(2.0f);
    posed_.draw();
    glLineWidth(1.0f);
}

void CursorLayer::body(Batch& out, const PosedSkeleton& p, const Frame& frame) {
    const double base = frame.cursor * frame.time_scale;
    auto at = [&](std::size_t j) {
        const glm::dvec3& g = p.joints[j];
        return glm::vec3(float(g.x), float(base + g.z * frame.skeleton_scale), float(-g.y));
    };
    io::CapsuleMesh mesh;
    for (std::size_t j = 0; j < p.joints.size(); ++j) {
        const int parent = (*p.parents)[j];
        if (parent < 0) continue;
        const glm::vec3 a = at(std::size_t(parent)), b = at(j);
        io::add_capsule(mesh, a, b, io::capsule_radius(glm::length(b - a)));
    }
    // One light from above and in front (GL y up), and some ambient, computed per vertex: the colour
    // shader has no lighting of its own.
    const glm::vec3 light = glm::normalize(glm::vec3(0.4f, 1.0f, 0.6f));
    std::vector<glm::vec4> shade(mesh.normals.size());
    for (std::size_t v = 0; v < shade.size(); ++v)
        shade[v] = glm::vec4(p.color * (0.45f + 0.75f * std::max(0.0f, glm::dot(mesh.normals[v], light))), 1.0f);
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        out.triangle(mesh.positions[a], mesh.positions[b], mesh.positions[c], shade[a], shade[b], shade[c]);
    }
}

void CursorLayer::skeleton(Batch& out, const io::Animation& anim, io::UpAxis up, int f, const Rigid2& m, double floor,
                           const Frame& frame, const glm::vec3& color) {
    const double base = frame.cursor * frame.time_scale;
    const io::Skeleton& skel = anim.skeleton;
    const glm::vec4 rgba(color * 0.55f, 1.0f);
    auto joint = [&](int j) {
        const glm::dvec3 g = io::to_ground(anim.at(f, j), up);
        return glm::vec3(float(m.apply_x(g.x, g.y)), float(base + (g.z - floor) * frame.skeleton_scale),
                         float(-m.apply_y(g.x, g.y)));
    };
    for (int j = 0; j < skel.size(); ++j)
        if (skel.parents[std::size_t(j)] >= 0) out.line(joint(skel.parents[std::size_t(j)]), joint(j), rgba);
}

void CursorLayer::joints(Batch& out, const PosedSkeleton& p, const Frame& frame) {
    const double base = frame.cursor * frame.time_scale;
    const glm::vec4 rgba(p.color * 0.55f, 1.0f);
    auto at = [&](std::size_t j) {
        const glm::dvec3& g = p.joints[j];
        return glm::vec3(float(g.x), float(base + g.z * frame.skeleton_scale), float(-g.y));
    };
    for (std::size_t j = 0; j < p.joints.size(); ++j)
        if ((*p.parents)[j] >= 0) out.line(at(std::size_t((*p.parents)[j])), at(j), rgba);
}

void CursorLayer::draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass, TextLayer& text) {
    if (ctx.bounds.empty || !(frame.layers.cursor || frame.layers.skeletons)) return;
    ctx.use(*ctx.color);
    const double ts = frame.time_scale, t = frame.cursor;
    const double x0 = std::floor(ctx.bounds.lo.x) - 1, x1 = std::ceil(ctx.bounds.hi.x) + 1;
    const double y0 = std::floor(ctx.bounds.lo.y) - 1, y1 = std::ceil(ctx.bounds.hi.y) + 1;
    if (translucent_pass) {
        if (!frame.layers.cursor) return;
        plane_.clear();
        plane_.quad(to_gl(x0, y0, t, ts), to_gl(x1, y0, t, ts), to_gl(x1, y1, t, ts), to_gl(x0, y1, t, ts),
                    glm::vec4(0.25f, 0.45f, 0.95f, 0.13f));
        plane_.draw();
        return;
    }
    lines_.clear();
    if (frame.layers.cursor) {
        const glm::vec4 edge(0.25f, 0.40f, 0.85f, 1.0f);
        lines_.line(to_gl(x0, y0, t, ts), to_gl(x1, y0, t, ts), edge);
        lines_.line(to_gl(x1, y0, t, ts), to_gl(x1, y1, t, ts), edge);
        lines_.line(to_gl(x1, y1, t, ts), to_gl(x0, y1, t, ts), edge);
        lines_.line(to_gl(x0, y1, t, ts), to_gl(x0, y0, t, ts), edge);
        if (frame.layers.labels) {
            char label[32];
            std::snprintf(label, sizeof label, "t = %.2f s", t);
            text.add(to_gl(x1, y1, t, ts), label, edge, Anchor::Left, LabelRole::Title);
        }
    }
    if (frame.layers.skeletons) skeletons(frame);
    glLineWidth(2.0f);
    lines_.draw();
    glLineWidth(1.0f);
}

}  // namespace mobb::render
