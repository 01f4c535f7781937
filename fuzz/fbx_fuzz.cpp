// libFuzzer entry point for the FBX (Assimp) reader: our skeleton search, key reading and sampling are
// instrumented, libassimp itself is not. Any input must load or throw LoadError, never crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mobb/io/assimp_reader.h"
#include "mobb/io/load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const mobb::io::assimp::Result result = mobb::io::assimp::load("fuzz.fbx", bytes, {});
        const mobb::Path path = mobb::io::path_of(result.animation, result.up);
        if (path.size() != std::size_t(result.animation.frames())) __builtin_trap();
    } catch (const mobb::io::LoadError&) {
    }
    return 0;
}
