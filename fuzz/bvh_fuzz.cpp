// libFuzzer entry point for the BVH reader: any input must parse or throw LoadError, never crash,
// hang or allocate without bound. Forward kinematics runs on whatever parses.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "bvh.h"
#include "mobb/io/load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const mobb::io::bvh::Document doc = mobb::io::bvh::parse(text, "fuzz.bvh");
        const mobb::io::Animation anim = mobb::io::bvh::animate(doc, 0.01);
        const mobb::Path path = mobb::io::path_of(anim, mobb::io::UpAxis::Y);
        if (path.size() != std::size_t(doc.frames)) __builtin_trap();
    } catch (const mobb::io::LoadError&) {
    }
    return 0;
}
