#include "prism_layer.h"

#include "space.h"

namespace mobb::render {

namespace {

// Ring edges at t0 and t1 (one ring when flat), a ring where the cursor cuts it (the walls where they
// stand now: with a time window, and from the top, the rings at t0 and t1 are out of sight) and the
// vertical edges between them.
void add_edges(const Prism& p, double ts, double cursor, const glm::vec4& color, Batch& out) {
    const std::size_t n = p.ground.size();
    const bool flat = p.t0 == p.t1, cut = p.t0 < cursor && cursor < p.t1;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& a = p.ground[i];
        const auto& b = p.ground[(i + 1) % n];
        if (n == 2 && i == 1) break;  // a segment has one edge
        out.line(to_gl(a[0], a[1], p.t0, ts), to_gl(b[0], b[1], p.t0, ts), color);
        if (flat) continue;
        out.line(to_gl(a[0], a[1], p.t1, ts), to_gl(b[0], b[1], p.t1, ts), color);
        if (cut) out.line(to_gl(a[0], a[1], cursor, ts), to_gl(b[0], b[1], cursor, ts), color);
        out.line(to_gl(a[0], a[1], p.t0, ts), to_gl(a[0], a[1], p.t1, ts), color);
    }
    if (n == 2 && !flat)
        out.line(to_gl(p.ground[1][0], p.ground[1][1], p.t0, ts), to_gl(p.ground[1][0], p.ground[1][1], p.t1, ts),
                 color);
}

void add_faces(const Prism& p, double ts, Batch& out) {
    const glm::vec4 color(p.color, p.fill);
    const std::size_t n = p.ground.size();
    for (std::size_t i = 0; i < n && n >= 2; ++i) {
        if (n == 2 && i == 1) break;
        const auto& a = p.ground[i];
        const auto& b = p.ground[(i + 1) % n];
        out.quad(to_gl(a[0], a[1], p.t0, ts), to_gl(b[0], b[1], p.t0, ts), to_gl(b[0], b[1], p.t1, ts),
                 to_gl(a[0], a[1], p.t1, ts), color);
    }
}

}  // namespace

void PrismLayer::draw(const Frame& frame, const DrawContext& ctx, bool translucent_pass) {
    if (frame.prisms.empty()) return;
    Batch& out = translucent_pass ? faces_ : edges_;
    out.clear();
    for (const Prism& p : frame.prisms) {
        if (p.on_top || p.ground.size() < 2) continue;
        if (!translucent_pass)
            add_edges(p, frame.time_scale, frame.cursor, glm::vec4(p.color, 1.0f), out);
        else if (p.fill > 0 && p.t0 != p.t1)
            add_faces(p, frame.time_scale, out);
    }
    if (out.empty()) return;
    ctx.use(*ctx.color);
    glLineWidth(1.5f);
    out.draw();
    glLineWidth(1.0f);
}

void PrismLayer::draw_on_top(const Frame& frame, const DrawContext& ctx) {
    top_.clear();
    for (const Prism& p : frame.prisms)
        if (p.on_top && p.ground.size() >= 2)
            add_edges(p, frame.time_scale, frame.cursor, glm::vec4(p.color, 1.0f), top_);
    if (top_.empty()) return;
    ctx.use(*ctx.color);
    glLineWidth(3.0f);
    top_.draw();
    glLineWidth(1.0f);
}

}  // namespace mobb::render
