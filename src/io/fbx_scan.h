// What Assimp does not tell about an FBX file, read from its bytes: connections that form a cycle (Assimp
// 5.2 follows model connections recursively and never returns on a cycle: a stack overflow), arrays longer
// than the file can hold (Assimp allocates them first), and whether a global setting is written at all
// (Assimp fills in defaults). Internal to mobb_io.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace mobb::io::fbx {

/// What would take Assimp down, found in one pass over the file's records (binary) or text (ASCII).
struct Hazards {
    /// An object id on a cycle of the file's connections ("C" records, src -> dst), or nothing. Counts
    /// every "C" record with a type string and two integer ids, wherever it stands (more than Assimp
    /// reads, never less); other bytes are left to Assimp's own checks.
    std::optional<std::int64_t> cycle;
    /// The length an array declares where the file cannot hold it, or nothing. ASCII (`*N` after a key):
    /// N over the file's size in bytes, each value taking at least one (capped at that size + 1). Binary:
    /// a zlib-compressed array whose values take more bytes than deflate can give its compressed ones
    /// (1,032 to 1). Assimp allocates the declared length before it reads a value: a 1.5 KB ASCII file
    /// declaring 77,777,777,773 key times asked for 622 GB (found by fuzz/fbx_fuzz in CI), a binary length
    /// word up to 4 GB. Binary arrays stored plain state their byte length, which Assimp checks itself.
    std::optional<std::uint64_t> impossible_array;
    /// The offset of a binary record whose property bytes run past the end of the file (and the NUL Assimp
    /// reads after it), or nothing.
    /// Assimp 5.2 adds that length (64 bits from version 7500) to a pointer before it compares it with the
    /// end: a length near 2^64 wraps, and an assertion aborts the process (found by fuzz/fbx_fuzz in CI).
    /// Shorter overruns Assimp refuses itself; refusing them here changes only the message.
    std::optional<std::size_t> overrun;
};
Hazards hazards(const std::string& bytes);

/// True when the file names the property `name` (e.g. "UnitScaleFactor") as a whole string: quoted in
/// ASCII FBX, a length-prefixed string property in binary FBX.
bool names_property(const std::string& bytes, const std::string& name);

}  // namespace mobb::io::fbx
