#include "image.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

#include "gl.h"
#include "mobb/core/assert.h"

namespace mobb::render {

void write_png(const std::string& file, const Image& image) {
    MOBB_ASSERT(image.width > 0 && image.height > 0 &&
                image.rgba.size() == std::size_t(image.width) * std::size_t(image.height) * 4);
    const std::string tmp = file + ".part";
    if (!stbi_write_png(tmp.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4)) {
        std::remove(tmp.c_str());
        throw std::runtime_error(file + ": cannot write PNG");
    }
    if (std::rename(tmp.c_str(), file.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw std::runtime_error(file + ": cannot write PNG");
    }
}

Image read_png(const std::string& file) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(file.c_str(), &w, &h, &n, 4);
    if (!data) throw std::runtime_error(file + ": cannot read PNG (" + stbi_failure_reason() + ")");
    Image image{w, h, std::vector<std::uint8_t>(data, data + std::size_t(w) * std::size_t(h) * 4)};
    stbi_image_free(data);
    return image;
}

Image read_pixels(int width, int height) {
    MOBB_ASSERT(width > 0 && height > 0);
    Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4)};
    std::vector<std::uint8_t> rows(image.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    const std::size_t stride = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(&rows[std::size_t(height - 1 - y) * stride], stride, &image.rgba[std::size_t(y) * stride]);
    return image;
}

}  // namespace mobb::render
