#include "disk_layer.h"

#include <cmath>

namespace mobb::render {

namespace {

/// Segments around a disk: smooth for ordinary scenes, coarse for crowds, where llvmpipe's vertex
/// work dominates (360,000 disks) and a disk is a few pixels wide anyway.
constexpr int kSegmentsFine = 16, kSegmentsCoarse = 8;
constexpr std::size_t kCoarseAbove = 100000;

struct MeshVertex {
    glm::vec3 pos, normal;
};

struct Mesh {
    std::vector<MeshVertex> vertices;
    std::vector<std::uint16_t> indices;
};

/// The unit cylinder, indexed: radius 1 around y, from y = 0 to 1, side and top cap. The bottom cap
/// is left out: in a stack it lies on the previous disk's top, and the ground hides the first one.
Mesh unit_cylinder(int segments) {
    Mesh m;
    const float two_pi = 6.28318530718f;
    const glm::vec3 up(0, 1, 0);
    for (int k = 0; k < segments; ++k) {
        const float a = two_pi * float(k) / float(segments);
        const glm::vec3 p(std::cos(a), 0, -std::sin(a));
        m.vertices.push_back({p, p});            // 4k: side, bottom
        m.vertices.push_back({p + up, p});       // 4k + 1: side, top
        m.vertices.push_back({p + up, up});      // 4k + 2: top cap rim
        m.vertices.push_back({p + up, up});      // 4k + 3: unused twin keeps the stride simple
    }
    const auto centre = std::uint16_t(m.vertices.size());
    m.vertices.push_back({up, up});
    for (int k = 0; k < segments; ++k) {
        const auto i = std::uint16_t(4 * k), j = std::uint16_t(4 * ((k + 1) % segments));
        m.indices.insert(m.indices.end(), {i, j, std::uint16_t(j + 1), i, std::uint16_t(j + 1), std::uint16_t(i + 1)});
        m.indices.insert(m.indices.end(), {centre, std::uint16_t(i + 2), std::uint16_t(j + 2)});
    }
    return m;
}

}  // namespace

std::vector<DiskInstance> disk_instances(const Path& path, const Placement& place) {
    const Rigid2 m = Rigid2::of(place);
    std::vector<DiskInstance> out;
    out.reserve(path.size());
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Sample& s = path.samples[i];
        out.emplace_back(float(m.apply_x(s.x, s.y)), float(m.apply_y(s.x, s.y)),
                         float(sample_time(place, path.dt, std::int64_t(i))), float(s.r));
    }
    return out;
}

DiskLayer::DiskLayer() {
    glGenBuffers(1, &mesh_);
    glGenBuffers(1, &indices_);
    set_segments(kSegmentsFine);
    marked_ = make_stack();
}

void DiskLayer::set_segments(int segments) {
    // Stacks' vertex arrays keep referring to the same buffers: only the contents change.
    const Mesh mesh = unit_cylinder(segments);
    glBindBuffer(GL_ARRAY_BUFFER, mesh_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(MeshVertex)), mesh.vertices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint16_t)), mesh.indices.data(), GL_STATIC_DRAW);
    mesh_indices_ = GLsizei(mesh.indices.size());
    segments_ = segments;
}

DiskLayer::~DiskLayer() {
    for (Stack& s : stacks_) {
        glDeleteBuffers(1, &s.vbo);
        glDeleteVertexArrays(1, &s.vao);
    }
    glDeleteBuffers(1, &marked_.vbo);
    glDeleteVertexArrays(1, &marked_.vao);
    glDeleteBuffers(1, &mesh_);
    glDeleteBuffers(1, &indices_);
}

DiskLayer::Stack DiskLayer::make_stack() {
    Stack s;
    glGenVertexArrays(1, &s.vao);
    glGenBuffers(1, &s.vbo);
    glBindVertexArray(s.vao);
    glBindBuffer(GL_ARRAY_BUFFER, mesh_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), reinterpret_cast<void*>(sizeof(glm::vec3)));
    glBindBuffer(GL_ARRAY_BUFFER, s.vbo);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(DiskInstance), nullptr);
    glVertexAttribDivisor(2, 1);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
    glBindVertexArray(0);
    return s;
}

void DiskLayer::upload(Stack& stack, const std::vector<DiskInstance>& disks) {
    glBindBuffer(GL_ARRAY_BUFFER, stack.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(disks.size() * sizeof(DiskInstance)), disks.data(), GL_DYNAMIC_DRAW);
    stack.count = GLsizei(disks.size());
}

void DiskLayer::rebuild(const Frame& frame) {
    std::size_t total = 0;
    for (const ClipView& clip : frame.clips) total += clip.tree->path().size();
    const int segments = total > kCoarseAbove ? kSegmentsCoarse : kSegmentsFine;
    if (segments != segments_) set_segments(segments);
    while (stacks_.size() < frame.clips.size()) stacks_.push_back(make_stack());
    for (std::size_t c = 0; c < frame.clips.size(); ++c) {
        const ClipView& clip = frame.clips[c];
        upload(stacks_[c], disk_instances(clip.tree->path(), clip.place));
        stacks_[c].dt = float(clip.tree->path().dt);
    }
}

void DiskLayer::draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass) {
    if (!frame.layers.disks || frame.layers.disks_translucent != translucent_pass) return;
    ctx.disk->use();
    ctx.disk->set("u_mvp", ctx.view_proj);
    ctx.disk->set("u_time_scale", float(frame.time_scale));
    ctx.disk->set("u_grow", 1.0f);
    const float alpha = translucent_pass ? 0.28f : 1.0f;
    for (std::size_t c = 0; c < frame.clips.size() && c < stacks_.size(); ++c) {
        if (!frame.clips[c].visible) continue;
        ctx.disk->set("u_dt", stacks_[c].dt);
        ctx.disk->set("u_color", glm::vec4(frame.clips[c].color, alpha));
        glBindVertexArray(stacks_[c].vao);
        glDrawElementsInstanced(GL_TRIANGLES, mesh_indices_, GL_UNSIGNED_SHORT, nullptr, stacks_[c].count);
    }
    glBindVertexArray(0);
}

void DiskLayer::draw_marked(const DrawContext& ctx, const std::vector<DiskInstance>& disks, double dt,
                            double time_scale, const glm::vec4& color, float grow) {
    if (disks.empty()) return;
    upload(marked_, disks);
    ctx.disk->use();
    ctx.disk->set("u_mvp", ctx.view_proj);
    ctx.disk->set("u_time_scale", float(time_scale));
    ctx.disk->set("u_dt", float(dt));
    ctx.disk->set("u_grow", grow);
    ctx.disk->set("u_color", color);
    glBindVertexArray(marked_.vao);
    glDrawElementsInstanced(GL_TRIANGLES, mesh_indices_, GL_UNSIGNED_SHORT, nullptr, marked_.count);
    glBindVertexArray(0);
}

}  // namespace mobb::render
