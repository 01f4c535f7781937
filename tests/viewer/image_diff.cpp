#include "image_diff.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace mobb::test {

Diff compare(const render::Image& expected, const render::Image& actual, const Tolerance& tolerance) {
    Diff d;
    d.same_size = expected.width == actual.width && expected.height == actual.height;
    if (!d.same_size) return d;
    d.image = expected;
    for (int y = 0; y < expected.height; ++y) {
        for (int x = 0; x < expected.width; ++x) {
            const std::uint8_t* e = expected.at(x, y);
            const std::uint8_t* a = actual.at(x, y);
            int worst = 0;
            for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(e[c]) - int(a[c])));
            d.largest = std::max(d.largest, worst);
            std::uint8_t* out = d.image.at(x, y);
            if (worst > tolerance.channel) {
                ++d.differing;
                out[0] = 255, out[1] = 0, out[2] = 0, out[3] = 255;
            } else {
                for (int c = 0; c < 3; ++c) out[c] = std::uint8_t(191 + e[c] / 4);
                out[3] = 255;
            }
        }
    }
    d.fraction = double(d.differing) / double(std::max(1, expected.width * expected.height));
    return d;
}

std::string write_failure(const std::string& dir, const std::string& name, const render::Image& expected,
                          const render::Image& actual, const Diff& diff) {
    std::filesystem::create_directories(dir);
    const std::string base = dir + "/" + name;
    if (expected.width > 0) render::write_png(base + ".expected.png", expected);
    render::write_png(base + ".actual.png", actual);
    if (diff.same_size) render::write_png(base + ".diff.png", diff.image);
    return base;
}

}  // namespace mobb::test
