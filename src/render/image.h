// RGBA8 images, top row first, and PNG files (stb_image / stb_image_write).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mobb::render {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  ///< width * height * 4, top row first

    std::uint8_t* at(int x, int y) { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
    const std::uint8_t* at(int x, int y) const {
        return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    }
};

/// Writes a PNG through a temporary file renamed into place, so a failure leaves no partial file.
/// Throws std::runtime_error naming the file.
void write_png(const std::string& file, const Image& image);

/// Reads a PNG as RGBA8; throws std::runtime_error naming the file.
Image read_png(const std::string& file);

/// The pixels of the bound read framebuffer, flipped to top row first.
Image read_pixels(int width, int height);

}  // namespace mobb::render
