// Skeleton animations from FBX, Collada and the other formats Assimp reads (Debian libassimp-dev 5.2).
// load_clip (mobb/io/load.h) dispatches here by extension; this header is for code that needs the
// reader alone (the fuzz target, bindings).
#pragma once
#include <string>
#include <vector>

#include "mobb/io/animation.h"
#include "mobb/io/load.h"

namespace mobb::io::assimp {

/// A skeleton animation as the file states it.
struct Result {
    Animation animation;                ///< world positions in file units, turned so the up axis is `up`
    UpAxis up = UpAxis::Y;              ///< the file's up axis (FBX UpAxis), else LoadOptions::up
    double unit = 0;                    ///< metres per file unit stated by the file (FBX UnitScaleFactor / 100);
                                        ///< 0 when the file states none
    std::string unit_reason;            ///< e.g. "FBX UnitScaleFactor 1: centimetres"
    double source_dt = 0;               ///< sample spacing in seconds as stored (animation.dt is it snapped)
    std::vector<std::string> warnings;  ///< "FILE: message"
};

/// True when Assimp has an importer for `extension` (with its dot, any case: ".fbx", ".DAE").
bool reads(const std::string& extension);

/// Every extension Assimp has an importer for, lower case with the dot, sorted, each once (".dae",
/// ".fbx", ...). Assimp's two-part ones (".mesh.xml") appear by their last part, as reads() sees them.
std::vector<std::string> extensions();

/// Reads `bytes` (the whole file; `file` names it in errors, and its extension tells Assimp the format).
/// Animation: the one named options.animation, else the first. Skeleton: the subtree of the first node,
/// depth first, that is a mesh bone or is moved by that animation (keys that change) and is not an FBX
/// null (the armature object), or of the node named options.root when it lies outside that subtree;
/// nodes carrying meshes are left out. Every node of the subtree is a joint, leaf bones included.
/// Samples: on the grid of the file's frame time (FBX frame rate; the median key spacing when the file
/// has none or its keys are denser) from the first to the last key; keys off that grid are interpolated
/// (linear, slerp) with a warning. Units and axes: FBX UnitScaleFactor and UpAxis/UpAxisSign when the file
/// writes them (Assimp would report FBX's defaults), else unit 0 and options.up.
/// Throws LoadError "FILE: message" (Assimp's own message for files it cannot parse; connections that
/// form a cycle are refused before Assimp sees them).
Result load(const std::string& file, const std::string& bytes, const LoadOptions& options);

}  // namespace mobb::io::assimp
