#include "context_osmesa.h"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl.h"
// osmesa.h wants GL/gl.h, which glad replaces (its include guard is already set); give it the
// calling-convention macros gl.h would have defined.
#ifndef GLAPI
#define GLAPI extern
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#include <GL/osmesa.h>

namespace mobb::render {

void pin_software_rasterizer() {
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    setenv("LP_NATIVE_VECTOR_WIDTH", "128", 1);
}

struct OsMesaContext::Impl {
    OSMesaContext context = nullptr;
    std::vector<unsigned char> buffer;
};

OsMesaContext::OsMesaContext(int width, int height) : impl_(std::make_unique<Impl>()) {
    pin_software_rasterizer();
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    impl_->context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!impl_->context) throw std::runtime_error("OSMesa: cannot create an OpenGL 3.3 core context");
    impl_->buffer.resize(std::size_t(width) * std::size_t(height) * 4);
    if (!OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
        OSMesaDestroyContext(impl_->context);
        throw std::runtime_error("OSMesa: cannot make the context current");
    }
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress))) {
        OSMesaDestroyContext(impl_->context);
        throw std::runtime_error("OSMesa: cannot load OpenGL functions");
    }
}

OsMesaContext::~OsMesaContext() { OSMesaDestroyContext(impl_->context); }

}  // namespace mobb::render
