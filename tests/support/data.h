// The real mocap data for tests: skipped with a reason when absent, a failure when required.
#pragma once
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "mobb/io/load.h"

namespace mobb::test {

inline bool data_required() {
    const char* v = std::getenv("MOBB_REQUIRE_DATA");
    return v && std::string(v) == "1";
}

/// Path of a file under the data folder (e.g. "cmu/002_01.bvh"), or "" when the data is absent.
inline std::string data_file(const std::string& relative) {
    const std::string dir = io::data_dir();
    return dir.empty() ? std::string() : dir + "/" + relative;
}

}  // namespace mobb::test

/// In a TEST body: skips (or fails under MOBB_REQUIRE_DATA=1) when the mocap folder is missing.
#define MOBB_REQUIRE_MOCAP()                                                                            \
    do {                                                                                                \
        if (mobb::io::data_dir().empty()) {                                                             \
            if (mobb::test::data_required()) FAIL() << "MOBB_REQUIRE_DATA=1 but no mocap folder found"; \
            GTEST_SKIP() << "mocap data not found: set MOBB_DATA or put it in ../shared/mocap";         \
        }                                                                                               \
    } while (0)
