// What a frame asks of the GL: draw calls and vertices submitted (indices or array vertices, times
// instances). Unlike frames per second they do not drift with the machine's load, so the benchmark
// reports them beside its timings and tests can bound them.
#pragma once
#include <cstddef>

namespace mobb::render {

struct DrawCounts {
    std::size_t calls = 0, vertices = 0;
};

/// Tallies one draw call submitting `vertices` vertices (every draw site of the renderer calls it).
void count_draw(std::size_t vertices);
/// Starts a new tally (Renderer::draw does, per frame) and reads it. The GL is used from one thread.
void reset_draw_counts();
DrawCounts draw_counts();

}  // namespace mobb::render
