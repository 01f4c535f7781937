// png_check FILE: exits 0 when the PNG shows a picture (many colours, not one flat fill), else 1.
// png_check FILE --differs-from OTHER: exits 0 when, in addition, the middle of the two same-sized
// images (the central half in each direction) differs in at least 10 % of its pixels - a window the
// test expected to open there, or a camera that moved.
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "image.h"

namespace {

std::size_t colours_of(const mobb::render::Image& image) {
    std::set<unsigned> colours;
    for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
        colours.insert(unsigned(image.rgba[i]) << 16 | unsigned(image.rgba[i + 1]) << 8 | image.rgba[i + 2]);
    return colours.size();
}

// Share of the pixels in the middle of a and b that differ by more than 8 in some channel.
double middle_difference(const mobb::render::Image& a, const mobb::render::Image& b) {
    std::size_t differ = 0, total = 0;
    for (int y = a.height / 4; y < 3 * a.height / 4; ++y)
        for (int x = a.width / 4; x < 3 * a.width / 4; ++x, ++total) {
            const std::uint8_t *p = a.at(x, y), *q = b.at(x, y);
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(p[c]) - int(q[c])) > 8) {
                    ++differ;
                    break;
                }
        }
    return total ? double(differ) / double(total) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool compare = argc == 4 && std::string(argv[2]) == "--differs-from";
    if (argc != 2 && !compare) {
        std::fprintf(stderr, "usage: png_check FILE.png [--differs-from OTHER.png]\n");
        return 2;
    }
    try {
        const mobb::render::Image image = mobb::render::read_png(argv[1]);
        const std::size_t colours = colours_of(image);
        std::printf("%s: %dx%d, %zu colours\n", argv[1], image.width, image.height, colours);
        if (colours < 64) return 1;
        if (!compare) return 0;
        const mobb::render::Image other = mobb::render::read_png(argv[3]);
        if (other.width != image.width || other.height != image.height) {
            std::fprintf(stderr, "error: %s is %dx%d\n", argv[3], other.width, other.height);
            return 1;
        }
        const double share = middle_difference(image, other);
        std::printf("middle differs from %s in %.1f %% of its pixels\n", argv[3], 100 * share);
        return share >= 0.10 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
