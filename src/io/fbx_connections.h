// A guard in front of Assimp: FBX object connections that form a cycle (Assimp 5.2 follows model
// connections recursively and never returns on a cycle: a stack overflow). Internal to mobb_io.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace mobb::io::fbx {

/// An object id on a cycle of the file's connections ("C" records, src -> dst, binary or ASCII FBX),
/// or nothing. Counts every "C" record with a type string and two integer ids, wherever it stands (more
/// than Assimp reads, never less); other bytes are left to Assimp's own checks.
std::optional<std::int64_t> connection_cycle(const std::string& bytes);

}  // namespace mobb::io::fbx
