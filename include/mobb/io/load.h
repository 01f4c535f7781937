// Loading clips from BVH and glTF/GLB files with the options shared by every subcommand.
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "mobb/io/animation.h"

namespace mobb::io {

/// A file that cannot be read or makes no sense. what() is one line naming the file and the place:
/// "FILE:LINE: message" for BVH, "FILE: ELEMENT: message" for glTF (e.g. "skins[0].joints[3]").
class LoadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct LoadOptions {
    UpAxis up = UpAxis::Y;              ///< --up y|z (glTF is always Y-up)
    std::optional<double> scale;        ///< --scale S (file units to metres); empty = auto (BVH)
    int frame_begin = 0;                ///< --frames A:B keeps frames A..B-1 (after loading)
    int frame_end = -1;                 ///< -1 = to the end
    std::optional<double> fps;          ///< --fps F: at each new sample time, the original frame at or just below it
    int skin = 0;                       ///< glTF: --skin K
    std::string animation;              ///< glTF: --animation NAME (empty = first)
};

/// A loaded clip: the animation (for drawing skeletons), its path (for the trees), and what was decided.
struct Clip {
    std::string file;
    Animation animation;
    Path path;
    UpAxis up = UpAxis::Y;
    double scale = 1.0;                 ///< metres per file unit
    std::string scale_reason;           ///< e.g. "auto: centimetres (standing height 172.3 units)"
    int source_frames = 0;              ///< frames in the file
    double source_dt = 0;               ///< frame time in the file (seconds)
    std::vector<std::string> warnings;  ///< e.g. root jumps of more than 0.5 m between frames
};

/// Loads a .bvh, .glb or .gltf file (by extension). Throws LoadError.
Clip load_clip(const std::string& file, const LoadOptions& options = {});

/// The data folder: $MOBB_DATA if set, else ../shared/mocap relative to the working directory,
/// else the one next to the source tree (compiled in). Empty if none exists.
std::string data_dir();

}  // namespace mobb::io
