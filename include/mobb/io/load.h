// Loading clips from BVH, glTF/GLB and FBX (and the other formats Assimp reads) with the options shared
// by every subcommand.
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "mobb/io/animation.h"

namespace mobb::io {

/// A file that cannot be read or makes no sense. what() is one line naming the file and the place:
/// "FILE:LINE: message" for BVH, "FILE: ELEMENT: message" for glTF (e.g. "skins[0].joints[3]"),
/// "FILE: message" for FBX and the other Assimp formats.
class LoadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Options applied by load_clip to every format, in this order: scale, frames, fps.
/// Invalid values (scale or fps not finite and positive, frames outside 0 <= A < B <= frames)
/// throw LoadError naming the file.
struct LoadOptions {
    UpAxis up = UpAxis::Y;        ///< --up y|z (glTF is always Y-up, FBX states its axis: Z is then ignored
                                  ///< with a warning)
    std::optional<double> scale;  ///< --scale S (file units to metres); empty = auto: 1 for glTF, the stated
                                  ///< unit for FBX, else guessed from the standing height (BVH, Collada)
    int frame_begin = 0;          ///< --frames A:B keeps frames A..B-1 (after loading)
    int frame_end = -1;           ///< -1 = to the end
    std::optional<double> fps;    ///< --fps F: at each new sample time k/F, the original frame at or just
                                  ///< below it (samples k/F < duration); dt becomes 1/F
    int skin = 0;                 ///< glTF: --skin K
    std::string animation;        ///< glTF, FBX: --animation NAME (empty = first)
    std::string root;             ///< --root NAME: the joint projected on the ground (empty = the skeleton's
                                  ///< root); FBX: a node outside the default skeleton makes its subtree the skeleton
};

/// Loader options as people write them on the command line and in scene files.
struct LoadOptionText {
    std::string up = "y";        ///< "y" or "z"
    std::string scale = "auto";  ///< metres per file unit, or "auto"
    std::string frames;          ///< "A:B" (B may be empty: to the end), or empty for every frame
    double fps = 0;              ///< 0: the file's rate
    int skin = 0;
    std::string animation;
    std::string root;
};

/// A finite number written as the whole of `text`. Throws std::invalid_argument
/// "WHAT: 'TEXT' is not a finite number".
double parse_number(const std::string& text, const std::string& what);

/// The options the text stands for. Throws std::invalid_argument with one line naming the option, e.g.
/// "--frames: expected whole numbers 0 <= A < B, got '5:2'".
LoadOptions parse_load_options(const LoadOptionText& text);

/// A loaded clip: the animation (for drawing skeletons), its path (for the trees), and what was decided.
struct Clip {
    std::string file;
    Animation animation;
    Path path;
    UpAxis up = UpAxis::Y;
    double scale = 1.0;                 ///< metres per file unit
    std::string scale_reason;           ///< e.g. "auto: centimetres (standing height 172.3 units)"
    int source_frames = 0;              ///< frames in the file
    double source_dt = 0;               ///< frame time in the file (seconds) as written; animation.dt is this
                                        ///< snapped to 1/N s when it is a rounded 1/N (0.016667 -> 1/60)
    std::vector<int> source_index;      ///< per sample: the file frame it was taken from
    std::vector<std::string> warnings;  ///< e.g. root jumps of more than 0.5 m between frames
};

/// A units guess for a skeleton `height` file units tall (its standing height, see load_clip).
struct ScaleGuess {
    double scale = 1.0;  ///< metres per file unit
    std::string reason;  ///< e.g. "auto: centimetres (standing height 172.3 units)"
};

/// Chooses among metres (1), centimetres (0.01), inches (0.0254) and the CMU unit (0.056444 m) the
/// one whose implied height is closest to 1.7 m on a log scale. Metres when height is not positive.
ScaleGuess guess_scale(double height);

/// Root ground-plane jumps of more than `threshold` metres between consecutive samples, as warnings
/// "FILE: frame K: root jumps D m from frame J ..." (K, J: file frames). Used by load_clip with 0.5 m.
std::vector<std::string> root_jumps(const Clip& clip, double threshold = 0.5);

/// Loads a .bvh, .glb, .gltf, .fbx, .dae or other file Assimp reads (by extension, case-insensitive; see
/// mobb/io/assimp_reader.h). Throws LoadError for a missing or unreadable file ("FILE: cannot open ..."),
/// an unknown extension, malformed content or bad options (--root naming no joint). Auto scale (BVH, and
/// Assimp files that state no unit): the standing height is the median over frames of the largest side of
/// the posed skeleton's bounding box, see guess_scale. Warnings: root jumps (root_jumps), ignored options,
/// uneven key times (Assimp formats).
Clip load_clip(const std::string& file, const LoadOptions& options = {});

/// The extensions load_clip reads, lower case with the dot, sorted, each once: .bvh, .glb, .gltf and
/// every one Assimp reads (.fbx, .dae, ...; see assimp::extensions). For file lists and pickers.
std::vector<std::string> clip_extensions();

/// True when load_clip reads `file` by its extension (any case); the content is not looked at.
bool is_clip_file(const std::string& file);

/// The data folder: $MOBB_DATA if set and an existing folder, else ../shared/mocap relative to the
/// working directory, else the one next to the source tree (compiled in). Empty if none exists.
/// Returned as an absolute, normalised path.
std::string data_dir();

/// A data file's path: absolute names as given, relative ones under data_dir(); with no data folder, the
/// copy shipped in the repository's assets/mocap (the default scene's two walks) when there is one. Throws
/// LoadError "FILE: no data folder (...)" when the name is relative, there is no data folder and no copy.
std::string resolve_data_file(const std::string& file);

/// The inverse, for files that name data: the path relative to data_dir() (with no data folder, to
/// assets/mocap) when the file lies inside it (symbolic links resolved), else the name as given.
std::string data_relative(const std::string& file);

}  // namespace mobb::io
