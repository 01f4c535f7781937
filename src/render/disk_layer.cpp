#include "disk_layer.h"
#include "draw_counts.h"
#include "mobb/core/assert.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mobb::render {

namespace {

/// Segments around a disk: smooth for ordinary scenes, coarse for crowds, where llvmpipe's vertex
/// work dominates (360,000 disks) and a disk is a few pixels wide anyway.
constexpr int kSegmentsFine = 16, kSegmentsCoarse = 8;
constexpr std::size_t kCoarseAbove = 100000;
/// Winding of the unit cylinder's outward faces (unit_cylinder()), kept by scaling and shearing.
constexpr GLenum kFrontFace = GL_CCW;

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
        m.vertices.push_back({p, p});        // 4k: side, bottom
        m.vertices.push_back({p + up, p});   // 4k + 1: side, top
        m.vertices.push_back({p + up, up});  // 4k + 2: top cap rim
        m.vertices.push_back({p + up, up});  // 4k + 3: unused twin keeps the stride simple
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

DiskLayer::DiskLayer() {
    glGenBuffers(1, &mesh_);
    glGenBuffers(1, &indices_);
    set_segments(kSegmentsFine);
    marked_ = make_stack(false);
}

void DiskLayer::set_segments(int segments) {
    MOBB_ASSERT(segments >= 3);
    // Stacks' vertex arrays keep referring to the same buffers: only the contents change.
    const Mesh mesh = unit_cylinder(segments);
    glBindBuffer(GL_ARRAY_BUFFER, mesh_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(MeshVertex)), mesh.vertices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint16_t)), mesh.indices.data(),
                 GL_STATIC_DRAW);
    mesh_indices_ = GLsizei(mesh.indices.size());
    segments_ = segments;
}

void DiskLayer::release(Tube& t) {
    if (t.vbo) glDeleteBuffers(1, &t.vbo);
    if (t.ibo) glDeleteBuffers(1, &t.ibo);
    if (t.vao) glDeleteVertexArrays(1, &t.vao);
    t = Tube{};
}

void DiskLayer::release(Stack& s) {
    if (s.vbo) glDeleteBuffers(1, &s.vbo);
    if (s.values) glDeleteBuffers(1, &s.values);
    if (s.vao) glDeleteVertexArrays(1, &s.vao);
    s = Stack{};
}

DiskLayer::~DiskLayer() {
    for (Clip& c : clips_) {
        for (Stack& s : c.lods) release(s);
        for (Tube& t : c.tubes) release(t);
    }
    release(marked_);
    glDeleteBuffers(1, &mesh_);
    glDeleteBuffers(1, &indices_);
}

/// A vertex array over the shared unit cylinder and a fresh instance buffer: DiskInstance (location 2)
/// alone, or DiskGroup (locations 2 and 3). Without location 3 the shader sees (0, 0, 0, 1): no
/// shear, one sample tall.
DiskLayer::Stack DiskLayer::make_stack(bool grouped) const {
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
    const GLsizei stride = grouped ? GLsizei(sizeof(DiskGroup)) : GLsizei(sizeof(DiskInstance));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, nullptr);
    glVertexAttribDivisor(2, 1);
    if (grouped) {
        glEnableVertexAttribArray(3);
        glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(DiskGroup, shift)));
        glVertexAttribDivisor(3, 1);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
    glBindVertexArray(0);
    return s;
}

void DiskLayer::upload(Stack& stack, const std::vector<DiskInstance>& disks) {
    glBindBuffer(GL_ARRAY_BUFFER, stack.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(disks.size() * sizeof(DiskInstance)), disks.data(), GL_DYNAMIC_DRAW);
    stack.count = GLsizei(disks.size());
}

void DiskLayer::upload(Stack& stack, const std::vector<DiskGroup>& groups) {
    glBindBuffer(GL_ARRAY_BUFFER, stack.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(groups.size() * sizeof(DiskGroup)), groups.data(), GL_STATIC_DRAW);
    stack.count = GLsizei(groups.size());
}

void DiskLayer::rebuild(const Frame& frame) {
    total_ = 0;
    for (const ClipView& clip : frame.clips) total_ += clip.tree->path().size();
    const int segments = total_ > kCoarseAbove ? kSegmentsCoarse : kSegmentsFine;
    if (segments != segments_) set_segments(segments);
    for (std::size_t c = frame.clips.size(); c < clips_.size(); ++c) {
        for (Stack& s : clips_[c].lods) release(s);
        for (Tube& t : clips_[c].tubes) release(t);
    }
    clips_.resize(frame.clips.size());
    for (std::size_t c = 0; c < frame.clips.size(); ++c) {
        const ClipView& clip = frame.clips[c];
        for (Stack& s : clips_[c].lods) {
            s.built = false;  // buffers are kept and refilled when next drawn
            s.values_revision = ~std::uint64_t(0);
        }
        for (Tube& t : clips_[c].tubes) t.built = false;
        clips_[c].chunks = chunk_bounds(clip.tree->path(), clip.place);
        clips_[c].dt = float(clip.tree->path().dt);
    }
}

int DiskLayer::level_of(int k) {
    int level = 0;
    while ((1 << level) < k && level + 1 < kLevels) ++level;
    return level;
}

DiskLayer::Stack& DiskLayer::stack_at(const ClipView& clip, Clip& c, int k) {
    const int level = level_of(k);
    Stack& s = c.lods[std::size_t(level)];
    if (s.built) return s;
    if (!s.vao) s = make_stack(level > 0);
    const std::vector<DiskInstance> disks = disk_instances(clip.tree->path(), clip.place);
    if (level == 0)
        upload(s, disks);
    else
        upload(s, group_disks(disks, 1 << level));
    s.built = true;
    return s;
}

// The samples inside the frame's time window: all without one. The clip planes cut the window's edges
// exactly; this only spares llvmpipe the instances wholly outside.
DiskLayer::SampleSpan DiskLayer::in_window(const Frame& frame, const ClipView& clip) {
    const auto n = std::int64_t(clip.tree->path().size());
    if (frame.window <= 0) return {0, n};
    const double dt = clip.tree->path().dt, t0 = clip.place.t0;
    const std::int64_t i0 =
        std::max<std::int64_t>(0, std::int64_t(std::floor((frame.cursor - frame.window - t0) / dt)));
    const std::int64_t i1 = std::min(n - 1, std::int64_t(std::floor((frame.cursor + frame.window - t0) / dt)));
    if (i1 < i0) return {0, 0};
    return {i0, i1 + 1};
}

bool DiskLayer::map_values(const Frame& frame, const ClipView& clip, Stack& s, int group) {
    const bool mapped = frame.layers.disk_colour != DiskColour::Clip && clip.sample_values &&
                        clip.sample_values->size() == clip.tree->path().size();
    if (!mapped) {
        glDisableVertexAttribArray(4);
        return false;
    }
    if (!s.values) glGenBuffers(1, &s.values);
    if (s.values_revision != frame.colour_revision) {
        const std::vector<float> v =
            group > 1 ? group_values(*clip.sample_values, group, frame.layers.disk_colour == DiskColour::Clearance)
                      : *clip.sample_values;
        glBindBuffer(GL_ARRAY_BUFFER, s.values);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
        s.values_revision = frame.colour_revision;
    }
    glEnableVertexAttribArray(4);
    glVertexAttribDivisor(4, 1);
    return true;
}

// Points the stack's instance attributes at its instance `first` (a GL 3.3 stand-in for a base instance).
void DiskLayer::point_at(const Stack& s, GLsizei first, bool grouped, bool mapped) {
    const GLsizei stride = grouped ? GLsizei(sizeof(DiskGroup)) : GLsizei(sizeof(DiskInstance));
    const std::size_t base = std::size_t(first) * std::size_t(stride);
    glBindBuffer(GL_ARRAY_BUFFER, s.vbo);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(base));
    if (grouped)
        glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<void*>(base + offsetof(DiskGroup, shift)));
    if (mapped) {
        glBindBuffer(GL_ARRAY_BUFFER, s.values);
        glVertexAttribPointer(4, 1, GL_FLOAT, GL_FALSE, sizeof(float),
                              reinterpret_cast<void*>(std::size_t(first) * sizeof(float)));
    }
}

namespace {
void chunk_gl(const Bounds& b, double time_scale, glm::vec3& lo, glm::vec3& hi) {
    const glm::vec3 a = to_gl(b.lo.x, b.lo.y, b.lo.z, time_scale), c = to_gl(b.hi.x, b.hi.y, b.hi.z, time_scale);
    lo = glm::min(a, c);
    hi = glm::max(a, c);
}
}  // namespace

GLsizei DiskLayer::draw_span(const Frame& frame, const DrawContext& ctx, std::size_t c, SampleSpan span, int k) {
    const ClipView& view = frame.clips[c];
    Clip& clip = clips_[c];
    Stack& s = stack_at(view, clip, k);
    const int group = 1 << level_of(k);  // samples per instance
    const auto g0 = GLsizei(span.first / group);
    const GLsizei g1 = std::min(GLsizei((span.end + group - 1) / group), s.count);
    if (g1 <= g0) return 0;
    ctx.disk->set("u_dt", clip.dt);
    glBindVertexArray(s.vao);
    const bool mapped = map_values(frame, view, s, group);
    ctx.disk->set("u_mapped", mapped ? 1 : 0);
    point_at(s, g0, group > 1, mapped);
    glDrawElementsInstanced(GL_TRIANGLES, mesh_indices_, GL_UNSIGNED_SHORT, nullptr, g1 - g0);
    count_draw(std::size_t(mesh_indices_) * std::size_t(g1 - g0));
    return g1 - g0;
}

// Consecutive chunks drawn at the same level of detail are one draw call: a stack's instances (or its
// tube's groups) lie in order in one buffer, so a run of chunks is one range of it.
std::vector<DiskLayer::Run> DiskLayer::runs_in_view(const Frame& frame, const DrawContext& ctx) {
    std::vector<Run> runs;
    for (std::size_t c = 0; c < frame.clips.size() && c < clips_.size(); ++c) {
        if (!frame.clips[c].visible) continue;
        const Clip& clip = clips_[c];
        const SampleSpan window = in_window(frame, frame.clips[c]);
        bool open = false;  // the last run is this clip's and may grow
        for (std::size_t q = 0; q < clip.chunks.size(); ++q) {
            const auto c0 = std::int64_t(q) * kDiskChunk;
            const SampleSpan span{std::max(c0, window.first), std::min(c0 + kDiskChunk, window.end)};
            if (span.first >= span.end) continue;
            glm::vec3 lo, hi;
            chunk_gl(clip.chunks[q], frame.time_scale, lo, hi);
            if (outside_view(ctx.view_proj, lo, hi)) {
                open = false;
                continue;
            }
            const int k =
                clip_lod(clip.chunks[q], double(clip.dt), frame.time_scale, total_, ctx.view_proj, ctx.height);
            if (open && runs.back().k == k && runs.back().span.end == span.first)
                runs.back().span.end = span.end;
            else
                runs.push_back({c, span, k});
            open = true;
        }
    }
    return runs;
}

void DiskLayer::draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass) {
    if (!frame.layers.disks || frame.layers.disks_translucent != translucent_pass) return;
    stats_ = DiskStats{};
    // Tubes stand for grouped cylinders where nothing shows a stack's inside or its groups' own values:
    // opaque, no time window cutting it open, each clip in its colour.
    const bool tubes = !translucent_pass && frame.window <= 0 && frame.layers.disk_colour == DiskColour::Clip;
    const auto tube = [&](const Run& r) { return tubes && level_of(r.k) > 0; };
    const std::vector<Run> runs = runs_in_view(frame, ctx);
    std::vector<bool> drawn(frame.clips.size(), false);
    const auto note = [&](const Run& r, GLsizei count) {
        if (count <= 0) return;
        drawn[r.clip] = true;
        stats_.instances += std::size_t(count);
        stats_.k_min = stats_.k_min ? std::min(stats_.k_min, r.k) : r.k;
        stats_.k_max = std::max(stats_.k_max, r.k);
    };
    // Opaque stacks are solids seen from outside: their back faces are hidden anyway, and culling them
    // spares llvmpipe half the rasterisation. Where the time window cuts a stack open, the disk below
    // shows its top cap instead of the stack's inside.
    if (!translucent_pass) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(kFrontFace);
    }
    const float alpha = translucent_pass ? 0.28f : 1.0f;
    ctx.use(*ctx.disk);
    ctx.disk->set("u_time_scale", float(frame.time_scale));
    ctx.disk->set("u_grow", 1.0f);
    // Caps inside a stack are hidden only where nothing cuts it open: no time window, opaque.
    ctx.disk->set("u_hide_caps", !translucent_pass && frame.window <= 0 ? 1 : 0);
    glVertexAttrib4f(3, 0.0f, 0.0f, 0.0f, 1.0f);  // what ungrouped stacks read at location 3
    const auto& table = colour_table(frame.disk_scale.map);
    ctx.disk->set("u_map", table.data(), kColourMapEntries);
    ctx.disk->set("u_lo", float(frame.disk_scale.lo));
    ctx.disk->set("u_hi", float(frame.disk_scale.hi));
    for (const Run& r : runs)
        if (!tube(r)) {
            ctx.disk->set("u_color", glm::vec4(frame.clips[r.clip].color, alpha));
            note(r, draw_span(frame, ctx, r.clip, r.span, r.k));
        }
    if (std::any_of(runs.begin(), runs.end(), tube)) {
        ctx.use(*ctx.tube);
        ctx.tube->set("u_time_scale", float(frame.time_scale));
        for (const Run& r : runs)
            if (tube(r)) {
                ctx.tube->set("u_color", glm::vec4(frame.clips[r.clip].color, alpha));
                note(r, draw_tube(frame, r.clip, r.span, r.k));
            }
    }
    for (std::size_t c = 0; c < drawn.size(); ++c)
        if (drawn[c]) stats_.disks += frame.clips[c].tree->path().size();
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
}

DiskLayer::Tube& DiskLayer::tube_at(const ClipView& clip, Clip& c, int k) const {
    const int level = level_of(k);
    Tube& t = c.tubes[std::size_t(level)];
    if (t.built) return t;
    if (!t.vao) {
        glGenVertexArrays(1, &t.vao);
        glGenBuffers(1, &t.vbo);
        glGenBuffers(1, &t.ibo);
        glBindVertexArray(t.vao);
        glBindBuffer(GL_ARRAY_BUFFER, t.vbo);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(TubeVertex), nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(TubeVertex),
                              reinterpret_cast<void*>(offsetof(TubeVertex, dir)));
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, t.ibo);
    }
    const Path& path = clip.tree->path();
    t.shape = tube_mesh(group_disks(disk_instances(path, clip.place), 1 << level), path.dt, segments_);
    glBindVertexArray(t.vao);
    glBindBuffer(GL_ARRAY_BUFFER, t.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(t.shape.vertices.size() * sizeof(TubeVertex)), t.shape.vertices.data(),
                 GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(t.shape.indices.size() * sizeof(std::uint32_t)),
                 t.shape.indices.data(), GL_STATIC_DRAW);
    t.shape.vertices = {};  // the buffers hold them; the shape keeps its index ranges
    t.shape.indices = {};
    t.built = true;
    return t;
}

GLsizei DiskLayer::draw_tube(const Frame& frame, std::size_t c, SampleSpan span, int k) {
    Tube& t = tube_at(frame.clips[c], clips_[c], k);
    const int group = 1 << level_of(k);
    const auto g0 = std::size_t(span.first / group);
    const std::size_t g1 = std::min(std::size_t((span.end + group - 1) / group), t.shape.groups);
    if (g1 <= g0) return 0;
    const std::size_t first = t.shape.first_index(g0), count = t.shape.end_index(g1) - first;
    glBindVertexArray(t.vao);
    glDrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT,
                   reinterpret_cast<void*>(first * sizeof(std::uint32_t)));
    count_draw(count);
    return GLsizei(g1 - g0);
}

void DiskLayer::draw_marked(const DrawContext& ctx, const std::vector<DiskInstance>& disks, double dt,
                            double time_scale, const glm::vec4& color, float grow) {
    if (disks.empty()) return;
    upload(marked_, disks);
    ctx.use(*ctx.disk);
    ctx.disk->set("u_time_scale", float(time_scale));
    ctx.disk->set("u_dt", float(dt));
    ctx.disk->set("u_grow", grow);
    ctx.disk->set("u_color", color);
    ctx.disk->set("u_mapped", 0);
    ctx.disk->set("u_hide_caps", 0);
    glVertexAttrib4f(3, 0.0f, 0.0f, 0.0f, 1.0f);
    glBindVertexArray(marked_.vao);
    glDrawElementsInstanced(GL_TRIANGLES, mesh_indices_, GL_UNSIGNED_SHORT, nullptr, marked_.count);
    count_draw(std::size_t(mesh_indices_) * std::size_t(marked_.count));
    glBindVertexArray(0);
}

}  // namespace mobb::render
