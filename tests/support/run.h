// Runs the `mobb` executable (MOBB_EXE) as a user would: arguments, optional stdin text, exit code,
// stdout and stderr.
#pragma once
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "files.h"

namespace mobb::test {

struct Result {
    int code = -1;
    std::string out, err;
};

inline Result run_mobb(const std::string& args, const std::string& input = "") {
    const std::string in = temp_file("in"), out = temp_file("out"), err = temp_file("err");
    std::ofstream(in) << input;
    const std::string cmd = std::string(MOBB_EXE) + " " + args + " <" + in + " >" + out + " 2>" + err;
    const int status = std::system(cmd.c_str());
    Result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

}  // namespace mobb::test
