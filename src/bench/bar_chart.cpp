#include "bar_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include <stb/stb_image_write.h>  // implementation in Debian's libstb

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace mobb::bench {

namespace {

struct Image {
    int w, h;
    std::vector<std::uint8_t> rgb;

    void fill(int x0, int y0, int x1, int y1, std::uint32_t c) {
        x0 = std::max(0, x0), y0 = std::max(0, y0), x1 = std::min(w, x1), y1 = std::min(h, y1);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                std::uint8_t* p = &rgb[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 3];
                p[0] = std::uint8_t(c >> 16), p[1] = std::uint8_t(c >> 8), p[2] = std::uint8_t(c);
            }
    }

    // Text at (x, y), top-left, scaled by `s`: stb_easy_font gives axis-aligned quads of 4 vertices.
    void text(int x, int y, const std::string& s, int scale, std::uint32_t c) {
        std::vector<char> buf(s.size() * 1024 + 256);  // up to ~16 quads of 64 bytes per glyph
        std::string copy = s;
        const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buf.data(), int(buf.size()));
        for (int q = 0; q < quads; ++q) {
            const float* v = reinterpret_cast<const float*>(buf.data() + std::size_t(q) * 64);
            float x0 = v[0], y0 = v[1], x1 = v[0], y1 = v[1];
            for (std::size_t k = 1; k < 4; ++k) {
                x0 = std::min(x0, v[k * 4]), x1 = std::max(x1, v[k * 4]);
                y0 = std::min(y0, v[k * 4 + 1]), y1 = std::max(y1, v[k * 4 + 1]);
            }
            fill(x + int(x0) * scale, y + int(y0) * scale, x + int(x1) * scale, y + int(y1) * scale, c);
        }
    }
};

}  // namespace

void write_bar_chart(const std::string& file, const std::string& title, const std::vector<Bar>& bars,
                     const std::string& unit) {
    // The label column as wide as the longest label, so that no bar is drawn over one; room on the
    // right for the longest value, and for the title.
    const int scale = 2, row = 34, top = 56, span = 600;
    const auto text_width = [&](std::string s) { return stb_easy_font_width(s.data()) * scale; };
    const auto value_text = [&](double v) {
        char value[64];
        std::snprintf(value, sizeof value, "%.3g %s", v, unit.c_str());
        return std::string(value);
    };
    int labels = 0, values = 0;
    for (const Bar& b : bars) {
        labels = std::max(labels, text_width(b.label));
        values = std::max(values, text_width(value_text(b.value)));
    }
    const int left = 16 + labels + 14, width = std::max(left + span + 8 + values + 16, 16 + text_width(title) + 16);
    Image img{width, top + row * int(bars.size()) + 24, {}};
    img.rgb.assign(std::size_t(img.w) * std::size_t(img.h) * 3, 255);
    img.text(16, 14, title, scale, 0x202020);
    double vmax = 0;
    for (const Bar& b : bars) vmax = std::max(vmax, b.value);
    img.fill(left - 1, top - 6, left, top + row * int(bars.size()), 0x808080);
    for (std::size_t k = 0; k < bars.size(); ++k) {
        const int y = top + row * int(k);
        img.text(16, y + 6, bars[k].label, scale, 0x202020);
        const int len = vmax > 0 ? int(std::lround(double(span) * bars[k].value / vmax)) : 0;
        img.fill(left, y + 2, left + std::max(1, len), y + row - 8, k % 2 ? 0x4a7fb5 : 0x2f5f8f);
        img.text(left + len + 8, y + 6, value_text(bars[k].value), scale, 0x202020);
    }
    if (!stbi_write_png(file.c_str(), img.w, img.h, 3, img.rgb.data(), img.w * 3))
        throw std::runtime_error(file + ": cannot write PNG");
}

}  // namespace mobb::bench
