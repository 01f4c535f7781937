// glTF 2.0 / GLB reader: a skin's joints, animated by one animation, as world positions per sample.
// Internal to mobb_io.
#pragma once
#include <string>
#include <vector>

#include "mobb/io/animation.h"

namespace mobb::io::gltf {

struct Result {
    Animation animation;                ///< metres as stored (glTF is metres, Y up)
    std::vector<std::string> warnings;  ///< "FILE: ELEMENT: message"
};

/// Reads `bytes` (a GLB, or glTF JSON whose external buffers are resolved next to `file`).
/// Skeleton: the joints of skins[skin], in skin order; each joint's parent is its nearest ancestor
/// that is also a joint; the root is the first joint with no joint ancestor. World positions include
/// every ancestor node (e.g. an Armature node). Samples: uniform from the first to the last key time
/// of the chosen animation (first, or the one named `animation`), dt = median key spacing snapped to
/// 1/N s; LINEAR (slerp for rotations), STEP and CUBICSPLINE samplers.
/// Throws LoadError "FILE: ELEMENT: message", e.g. "f.glb: animations[0].samplers[2]: ...".
Result load(const std::string& file, const std::string& bytes, int skin, const std::string& animation);

}  // namespace mobb::io::gltf
