// Shared by the render tests: data availability, scene paths, rendering a scene headless.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include <unistd.h>

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

/// A small deterministic crowd recorded by the real `mobb crowd` (the graph ships in assets/graphs,
/// its clip paths need no mocap data; the skeletons do). Written once per test process, to a file of
/// its own: ctest -j runs the discovered tests as parallel processes.
inline std::string crowd_record() {
    struct Record {
        std::string path;
        ~Record() {
            if (!path.empty()) std::remove(path.c_str());
        }
    };
    static const Record record = [] {
        const std::string out = std::string(MOBB_TEST_OUT) + "/crowd_record_" + std::to_string(getpid()) + ".json";
        const std::string cmd = std::string("\"") + MOBB_EXE + "\" crowd --quiet --graph \"" + MOBB_GRAPH +
                                "\" --agents 12 --world 12x12 --seconds 8 --seed 3 --select wander --record \"" + out +
                                "\" > /dev/null";
        return Record{std::system(cmd.c_str()) == 0 ? out : std::string()};
    }();
    return record.path;
}

/// A record of the shipped scenario `name` (seed 1), made once per test process.
inline std::string scenario_record(const std::string& name) {
    struct Made : std::map<std::string, std::string> {
        ~Made() {
            for (const auto& [n, path] : *this)
                if (!path.empty()) std::remove(path.c_str());
        }
    };
    static Made made;
    if (made.count(name)) return made[name];
    const std::string out = std::string(MOBB_TEST_OUT) + "/scenario_" + name + "_" + std::to_string(getpid()) + ".json";
    const std::string cmd = std::string("\"") + MOBB_EXE + "\" crowd --quiet --graph \"" + MOBB_GRAPH +
                            "\" --scenario \"" + MOBB_SOURCE_DIR + "/assets/scenarios/" + name + ".json\" --record \"" +
                            out + "\" > /dev/null";
    return made[name] = std::system(cmd.c_str()) == 0 ? out : std::string();
}

}  // namespace mobb::test

/// Skips the test without the mocap data, or fails when MOBB_REQUIRE_DATA=1.
#define MOBB_NEEDS_MOCAP()                                                                       \
    do {                                                                                         \
        if (!mobb::test::have_mocap()) {                                                         \
            if (mobb::test::require_data()) FAIL() << "mocap data missing, MOBB_REQUIRE_DATA=1"; \
            GTEST_SKIP() << "mocap data not found (set MOBB_DATA)";                              \
        }                                                                                        \
    } while (0)
