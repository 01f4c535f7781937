// Helpers for the io tests: temporary files, the real-data gate, LoadError checks.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mobb/io/load.h"

namespace mobb::test {

/// A fresh folder under the system temp folder, removed with everything in it on destruction.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    /// Writes `bytes` to path()/name and returns the full path.
    std::string write(const std::string& name, const std::string& bytes) const;

private:
    std::filesystem::path path_;
};

/// The data folder if it holds cmu/ and gltf/, else empty.
std::string mocap_dir();

/// Real-data tests derive from this: they are skipped (with the reason) when the data folder is
/// missing, and fail instead when MOBB_REQUIRE_DATA=1.
class DataTest : public ::testing::Test {
protected:
    void SetUp() override;
    std::string cmu(const std::string& name) const { return dir_ + "/cmu/" + name + ".bvh"; }
    std::string glb(const std::string& name) const { return dir_ + "/gltf/" + name + ".glb"; }
    std::string dir_;
};

/// Skips or fails like DataTest; for parameterised tests. Use: MOBB_NEED_DATA(dir);
#define MOBB_NEED_DATA(dir)                                                               \
    const std::string dir = ::mobb::test::mocap_dir();                                    \
    if (dir.empty()) {                                                                    \
        if (::mobb::test::data_required()) FAIL() << ::mobb::test::missing_data_reason(); \
        GTEST_SKIP() << ::mobb::test::missing_data_reason();                              \
    }

bool data_required();
std::string missing_data_reason();

/// Runs `f`, expects a LoadError and returns its message ("" and a test failure if none was thrown).
std::string load_error(const std::function<void()>& f);

/// Base64 (for glTF data URIs).
std::string base64(const std::string& bytes);

/// Little-endian bytes of float32 values (glTF buffers).
std::string floats(const std::vector<float>& values);

/// A GLB container around a JSON text and an optional BIN chunk.
std::string make_glb(const std::string& json, const std::string& bin);

}  // namespace mobb::test
