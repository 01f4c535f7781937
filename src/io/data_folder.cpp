// The data folder and the files named relative to it (scenes and motion graphs name their clips so); with
// no data folder, the motion capture shipped in the repository (assets/mocap: the default scene's walks).
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "mobb/io/load.h"

namespace mobb::io {

namespace {

namespace fs = std::filesystem;

bool usable_folder(const fs::path& path) {
    std::error_code ec;
    return !path.empty() && fs::is_directory(path, ec);
}

std::string absolute_string(const fs::path& path) {
    std::error_code ec;
    const fs::path abs = fs::absolute(path, ec);
    return (ec ? path : abs).lexically_normal().string();
}

// The shipped copy of `file` (a name relative to the data folder), empty when none is shipped.
std::string shipped_file(const fs::path& file) {
#ifdef MOBB_SHIPPED_MOCAP_DIR
    const fs::path name = file.lexically_normal();
    std::error_code ec;
    if (name.empty() || *name.begin() == "..") return {};
    const fs::path shipped = fs::path(MOBB_SHIPPED_MOCAP_DIR) / name;
    if (fs::is_regular_file(shipped, ec)) return shipped.string();
#else
    (void)file;
#endif
    return {};
}

// `file` relative to folder `base` when it lies inside it, else empty. Both canonical: either may be
// reached through a symbolic link.
std::string relative_inside(const std::string& file, const std::string& base) {
    std::error_code ec;
    const fs::path abs = fs::weakly_canonical(fs::absolute(file), ec);
    if (ec) return {};
    const fs::path canonical_base = fs::weakly_canonical(base, ec);
    if (ec) return {};
    const fs::path rel = abs.lexically_relative(canonical_base);
    if (rel.empty() || *rel.begin() == "..") return {};
    return rel.generic_string();
}

}  // namespace

std::string data_dir() {
    if (const char* env = std::getenv("MOBB_DATA"); env != nullptr && usable_folder(env)) return absolute_string(env);
    if (usable_folder("../shared/mocap")) return absolute_string("../shared/mocap");
#ifdef MOBB_DEFAULT_DATA_DIR
    if (usable_folder(MOBB_DEFAULT_DATA_DIR)) return absolute_string(MOBB_DEFAULT_DATA_DIR);
#endif
    return {};
}

std::string resolve_data_file(const std::string& file) {
    const fs::path p(file);
    if (p.is_absolute()) return file;
    const std::string dir = data_dir();
    if (!dir.empty()) return (fs::path(dir) / p).string();
    if (std::string shipped = shipped_file(p); !shipped.empty()) return shipped;
    throw LoadError(file + ": no data folder (set MOBB_DATA or run next to ../shared/mocap)");
}

std::string data_relative(const std::string& file) {
    std::string dir = data_dir();
#ifdef MOBB_SHIPPED_MOCAP_DIR
    if (dir.empty()) dir = MOBB_SHIPPED_MOCAP_DIR;  // the inverse of resolve_data_file's fallback
#endif
    if (dir.empty()) return file;
    const std::string rel = relative_inside(file, dir);
    return rel.empty() ? file : rel;
}

}  // namespace mobb::io
