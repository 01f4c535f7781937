// png_check FILE: exits 0 when the PNG shows a picture (many colours, not one flat fill), else 1.
#include <cstdio>
#include <set>

#include "image.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: png_check FILE.png\n");
        return 2;
    }
    try {
        const mobb::render::Image image = mobb::render::read_png(argv[1]);
        std::set<unsigned> colours;
        for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
            colours.insert(unsigned(image.rgba[i]) << 16 | unsigned(image.rgba[i + 1]) << 8 | image.rgba[i + 2]);
        std::printf("%s: %dx%d, %zu colours\n", argv[1], image.width, image.height, colours.size());
        return colours.size() >= 64 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
