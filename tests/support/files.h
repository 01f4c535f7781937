// Files for tests: names of this process's own (ctest -j runs a binary's tests as parallel
// processes, which must not share a file) and whole-file reads.
#pragma once
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace mobb::test {

/// A path in the test temp folder, prefixed with this process's id.
inline std::string temp_file(const std::string& name) {
    return testing::TempDir() + "mobb_" + std::to_string(::getpid()) + "_" + name;
}

/// The whole file as bytes ("" when it cannot be read).
inline std::string slurp(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// The error `f` throws ("" when none), checked to be one line that starts with `file` (as every bad-input
/// error is).
template <class F>
std::string file_error(const std::string& file, F&& f) {
    try {
        f();
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind(file + ": ", 0), 0u) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        return m;
    }
    return "";
}

}  // namespace mobb::test
