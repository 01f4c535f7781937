// The visible space-time picture as a glTF binary: disk stacks and boxes as meshes with materials,
// in metres, time on the up axis (space-time (x, y, t) -> glTF (x, t * time_scale, -y)).
#pragma once
#include <string>

#include "state.h"

namespace mobb::viewer {

struct GltfSummary {
    int meshes = 0, nodes = 0, materials = 0;
};

/// Writes FILE (.glb) through a temporary file renamed into place. Throws std::runtime_error.
GltfSummary export_gltf(const State& state, const std::string& file);

}  // namespace mobb::viewer
