// Shared by the render tests: data availability, scene paths, rendering a scene headless.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "mobb/io/load.h"

namespace mobb::test {

inline std::string test_scene(const std::string& name) { return std::string(MOBB_TEST_SCENES) + "/" + name; }

/// The CMU clips the scenes use are present.
inline bool have_mocap() {
    const std::string dir = io::data_dir();
    return !dir.empty() && std::filesystem::exists(dir + "/cmu/007_01.bvh") &&
           std::filesystem::exists(dir + "/cmu/005_01.bvh") && std::filesystem::exists(dir + "/cmu/001_01.bvh");
}

inline bool require_data() {
    const char* v = std::getenv("MOBB_REQUIRE_DATA");
    return v && std::string(v) == "1";
}

}  // namespace mobb::test

/// Skips the test without the mocap data, or fails when MOBB_REQUIRE_DATA=1.
#define MOBB_NEEDS_MOCAP()                                                                   \
    do {                                                                                     \
        if (!mobb::test::have_mocap()) {                                                     \
            if (mobb::test::require_data()) FAIL() << "mocap data missing, MOBB_REQUIRE_DATA=1"; \
            GTEST_SKIP() << "mocap data not found (set MOBB_DATA)";                          \
        }                                                                                    \
    } while (0)
