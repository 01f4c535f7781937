// The binary buffer of a glTF model, shared by the glTF export (mobb/io/export.h) and the viewer's scene
// export: their data go into buffer 0 of a tinygltf model, one buffer view at a time. Callers include
// <tiny_gltf.h>.
#pragma once
#include <cstddef>

namespace tinygltf {
class Model;
}

namespace mobb::io {

/// Appends `bytes` bytes from `data` to buffer 0 of `model` (which must exist) at the next multiple of 4
/// bytes (glTF aligns an accessor's data to its component size, 4 bytes at the most here), as a new buffer
/// view with `target` (TINYGLTF_TARGET_*, 0 for none). Returns the view's index.
int append_buffer_view(tinygltf::Model& model, const void* data, std::size_t bytes, int target);

}  // namespace mobb::io
