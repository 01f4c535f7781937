// column_check BEFORE.png AFTER.png X0 Y0 X1 Y1: exits 0 when, in the rectangle [X0, X1) x [Y0, Y1) of
// two same-sized window screenshots, the 3D view's background (the renderer's clear colour) shows in
// AFTER (at least 30 % of the pixels) and not in BEFORE (under 5 %): a panel column stood there, and
// once collapsed the viewport took its place.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "image.h"

namespace {

/// Share of the rectangle's pixels within 6 of the clear colour (0.965, 0.965, 0.972) in every channel.
double background_share(const mobb::render::Image& image, int x0, int y0, int x1, int y1) {
    const int clear[3] = {246, 246, 248};
    std::size_t hits = 0, total = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++total) {
            const std::uint8_t* p = image.at(x, y);
            bool near = true;
            for (int c = 0; c < 3; ++c) near = near && std::abs(int(p[c]) - clear[c]) <= 6;
            hits += near ? 1 : 0;
        }
    return total ? double(hits) / double(total) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 7) {
        std::fprintf(stderr, "usage: column_check BEFORE.png AFTER.png X0 Y0 X1 Y1\n");
        return 2;
    }
    try {
        const mobb::render::Image before = mobb::render::read_png(argv[1]), after = mobb::render::read_png(argv[2]);
        const int x0 = std::atoi(argv[3]), y0 = std::atoi(argv[4]), x1 = std::atoi(argv[5]), y1 = std::atoi(argv[6]);
        if (before.width != after.width || before.height != after.height || x1 > after.width || y1 > after.height ||
            x0 < 0 || y0 < 0 || x0 >= x1 || y0 >= y1) {
            std::fprintf(stderr, "error: images %dx%d and %dx%d, rectangle %d,%d..%d,%d\n", before.width, before.height,
                         after.width, after.height, x0, y0, x1, y1);
            return 2;
        }
        const double was = background_share(before, x0, y0, x1, y1), now = background_share(after, x0, y0, x1, y1);
        std::printf("3D view background in the column's place: %.1f %% before, %.1f %% after\n", 100 * was, 100 * now);
        return was < 0.05 && now >= 0.30 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
}
