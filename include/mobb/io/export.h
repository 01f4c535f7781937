// Writing animated skeletons for other tools: glTF 2.0 (.glb / .gltf, through tinygltf) and BVH.
// The skeletons are joint positions per frame (what io::Animation holds for every format), so every joint
// is animated by translation alone: rotations stay the identity, and the positions come back exactly.
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace mobb::io {

/// A file that cannot be written, or data that cannot go into one: "FILE: message", one line.
class ExportError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A joint hierarchy shared by every skeleton of a scene. Joint 0 is the root; parents precede children.
struct ExportRig {
    std::vector<std::string> names;
    std::vector<int> parents;  ///< -1 for joint 0
};

/// One animated skeleton: joint positions in mobb's ground coordinates (x, y, h), metres, h up, frame-major:
/// positions[f * joints + j]. Single precision, as glTF stores them (a micrometre at 100 m).
struct ExportSkeleton {
    std::string name;
    std::vector<glm::vec3> positions;
    std::array<float, 3> color{0.6f, 0.6f, 0.6f};  ///< of its body (linear RGB)
};

/// A static shape: a ground polygon (metres, either orientation; two points make a segment) raised to
/// `height` (0: flat on the ground, a goal's disk).
struct ExportShape {
    std::string name;
    std::vector<std::array<double, 2>> ground;
    double height = 1.0;
    std::array<float, 3> color{0.5f, 0.5f, 0.5f};
};

struct ExportScene {
    ExportRig rig;
    double dt = 1.0 / 30.0;  ///< seconds between frames
    int frames = 0;
    double start = 0;  ///< time of frame 0 in the animation (seconds)
    std::vector<ExportSkeleton> skeletons;
    std::vector<ExportShape> shapes;
    bool bodies = false;  ///< a capsule per bone, skinned to the bone's two joints
};

/// glTF 2.0, Y up, metres: ground (x, y, h) is glTF (x, h, -y). Per skeleton an armature node (its name,
/// no transform) holding the joints' node hierarchy, and one skin (skin K is skeletons[K], its joint 0 the
/// rig's joint 0), one animation ("crowd") with a LINEAR
/// translation channel per joint, frame f at time start + f dt; shapes as meshes; with `bodies` one skinned
/// mesh per skeleton. Binary (.glb) or text with the buffer embedded (.gltf), by extension. Written to a
/// temporary file renamed into place. Returns the file's size in bytes. Throws ExportError.
std::uintmax_t write_gltf(const ExportScene& scene, const std::string& file);

/// BVH of one skeleton of the scene, Y up, metres: the rig's hierarchy (leaf joints get a zero End Site),
/// every joint with position channels only (Xposition Yposition Zposition), OFFSETs those of frame 0, so
/// world positions come back exactly (to the 6 decimals written). Written through a temporary file.
/// Returns the file's size. Throws ExportError.
std::uintmax_t write_bvh(const ExportScene& scene, int skeleton, const std::string& file);

}  // namespace mobb::io
