// The data folder and the files named relative to it (scenes and motion graphs name their clips so).
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
    if (dir.empty()) throw LoadError(file + ": no data folder (set MOBB_DATA or run next to ../shared/mocap)");
    return (fs::path(dir) / p).string();
}

std::string data_relative(const std::string& file) {
    const std::string dir = data_dir();
    std::error_code ec;
    if (dir.empty()) return file;
    // Both sides canonical: the data folder may be reached through a symbolic link.
    const fs::path abs = fs::weakly_canonical(fs::absolute(file), ec);
    if (ec) return file;
    const fs::path base = fs::weakly_canonical(dir, ec);
    if (ec) return file;
    const fs::path rel = abs.lexically_relative(base);
    if (rel.empty() || *rel.begin() == "..") return file;
    return rel.generic_string();
}

}  // namespace mobb::io
