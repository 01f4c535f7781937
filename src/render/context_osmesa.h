// A headless OpenGL 3.3+ core context through OSMesa (llvmpipe): no X server, no GLFW.
#pragma once
#include <memory>

namespace mobb::render {

/// Pins Mesa's software rasterizer (llvmpipe, 128-bit vectors) so images match from machine to
/// machine. Called before the context is created; overrides the environment.
void pin_software_rasterizer();

class OsMesaContext {
public:
    /// Creates the context, makes it current and loads GL through glad. Throws std::runtime_error.
    OsMesaContext(int width, int height);
    ~OsMesaContext();
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace mobb::render
