#include "draw_counts.h"

namespace mobb::render {

namespace {
DrawCounts tally;
}  // namespace

void count_draw(std::size_t vertices) {
    ++tally.calls;
    tally.vertices += vertices;
}

void reset_draw_counts() { tally = DrawCounts{}; }

DrawCounts draw_counts() { return tally; }

}  // namespace mobb::render
