// libFuzzer entry point for the glTF/GLB reader (our validation and sampling; libtinygltf itself is
// not instrumented): any input must load or throw LoadError, never crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "gltf.h"
#include "mobb/io/load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const mobb::io::gltf::Result result = mobb::io::gltf::load("fuzz.gltf", bytes, 0, "");
        const mobb::Path path = mobb::io::path_of(result.animation, mobb::io::UpAxis::Y);
        if (path.size() != std::size_t(result.animation.frames())) __builtin_trap();
    } catch (const mobb::io::LoadError&) {
    }
    return 0;
}
