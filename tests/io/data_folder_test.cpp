// The data folder resolution with no data folder at all, as in a clone alone: src/io/data_folder.cpp built
// into this test with no folder next to the source tree (MOBB_DEFAULT_DATA_DIR names one that does not
// exist) and the repository's assets/mocap as the shipped clips (tests/io/CMakeLists.txt).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "mobb/io/load.h"

namespace mobb::io {
namespace {

namespace fs = std::filesystem;

// For one test: MOBB_DATA unset and the working directory two levels down a
// fresh temporary folder, so that ../shared/mocap exists nowhere; both restored afterwards.
class NoDataFolder {
public:
    NoDataFolder() {
        if (const char* old = std::getenv("MOBB_DATA")) old_data_ = old;
        ::unsetenv("MOBB_DATA");
        std::string pattern = (fs::temp_directory_path() / "mobb-data-folder-XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
        root_ = pattern;
        old_cwd_ = fs::current_path();
        fs::create_directories(root_ / "a" / "b");
        fs::current_path(root_ / "a" / "b");
    }
    ~NoDataFolder() {
        std::error_code ec;
        fs::current_path(old_cwd_, ec);
        fs::remove_all(root_, ec);
        if (old_data_)
            ::setenv("MOBB_DATA", old_data_->c_str(), 1);
        else
            ::unsetenv("MOBB_DATA");
    }
    NoDataFolder(const NoDataFolder&) = delete;
    NoDataFolder& operator=(const NoDataFolder&) = delete;
    const fs::path& root() const { return root_; }

private:
    std::optional<std::string> old_data_;
    fs::path old_cwd_;
    fs::path root_;
};

std::string shipped(const std::string& name) { return (fs::path(MOBB_SHIPPED_MOCAP_DIR) / name).string(); }

std::string bytes(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The default scene's two walks resolve to the shipped copies; any other clip still needs the data folder.
TEST(DataFolderAlone, ShippedWalksResolveOthersSayNoDataFolder) {
    const NoDataFolder alone;
    ASSERT_EQ(data_dir(), "");
    for (const char* name : {"cmu/007_01.bvh", "cmu/005_01.bvh"}) {
        EXPECT_EQ(resolve_data_file(name), shipped(name));
        EXPECT_TRUE(fs::is_regular_file(resolve_data_file(name))) << name;
    }
    for (const char* name : {"cmu/002_01.bvh", "gltf/002_01.glb", "../mocap/cmu/007_01.bvh"}) {
        try {
            resolve_data_file(name);
            ADD_FAILURE() << name << " resolved with no data folder";
        } catch (const LoadError& e) {
            EXPECT_EQ(std::string(e.what()),
                      std::string(name) + ": no data folder (set MOBB_DATA or run next to ../shared/mocap)");
        }
    }
    EXPECT_EQ(resolve_data_file("/abs/y.bvh"), "/abs/y.bvh");
}

// The inverse: a shipped file is named relative to assets/mocap, a file elsewhere as given.
TEST(DataFolderAlone, ShippedFilesAreNamedRelative) {
    const NoDataFolder alone;
    ASSERT_EQ(data_dir(), "");
    EXPECT_EQ(data_relative(shipped("cmu/005_01.bvh")), "cmu/005_01.bvh");
    EXPECT_EQ(data_relative("/elsewhere/y.bvh"), "/elsewhere/y.bvh");
}

// A data folder, even one without the walks, is read before the shipped copies.
TEST(DataFolderAlone, DataFolderComesFirst) {
    const NoDataFolder alone;
    const fs::path data = alone.root() / "data";
    fs::create_directories(data);
    ::setenv("MOBB_DATA", data.c_str(), 1);
    ASSERT_EQ(data_dir(), data.string());
    EXPECT_EQ(resolve_data_file("cmu/007_01.bvh"), (data / "cmu/007_01.bvh").string());
    EXPECT_EQ(data_relative(shipped("cmu/007_01.bvh")), shipped("cmu/007_01.bvh"));
}

// The shipped walks are the data folder's files, byte for byte (skipped without the data, a failure when
// MOBB_REQUIRE_DATA=1).
TEST(DataFolderAlone, ShippedWalksAreTheDataFoldersFiles) {
    const char* env = std::getenv("MOBB_DATA");
    std::error_code ec;
    const fs::path data = env != nullptr && fs::is_directory(env, ec) ? fs::path(env) : fs::path(MOBB_DATA_GUESS);
    if (!fs::is_regular_file(data / "cmu/007_01.bvh", ec)) {
        const char* required = std::getenv("MOBB_REQUIRE_DATA");
        if (required != nullptr && std::string(required) == "1") FAIL() << "MOBB_REQUIRE_DATA=1 but no " << data;
        GTEST_SKIP() << "mocap data not found in " << data << ": set MOBB_DATA or put it in ../shared/mocap";
    }
    for (const char* name : {"cmu/007_01.bvh", "cmu/005_01.bvh"}) {
        const std::string copy = bytes(shipped(name));
        EXPECT_GT(copy.size(), 100000U) << name;
        EXPECT_TRUE(copy == bytes((data / name).string())) << name << " differs from " << data / name;
    }
}

}  // namespace
}  // namespace mobb::io
