// An offscreen multisampled framebuffer: headless images are drawn here, then resolved and read.
#pragma once
#include "gl.h"
#include "image.h"

namespace mobb::render {

class Target {
public:
    Target(int width, int height, int samples = 4);
    ~Target();
    Target(const Target&) = delete;
    Target& operator=(const Target&) = delete;

    void bind() const;   ///< draw into the multisampled buffer
    Image read() const;  ///< resolve and read back, top row first

private:
    int width_, height_;
    GLuint msaa_fbo_ = 0, msaa_color_ = 0, msaa_depth_ = 0;
    GLuint fbo_ = 0, color_ = 0;
};

}  // namespace mobb::render
