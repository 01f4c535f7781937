// libFuzzer entry point for the HDF5 crowd-record reader (ours: src/crowd/record_h5_read.cpp, h5.cpp and
// the JSON reader's checks; libhdf5 itself is not instrumented): any file must read or throw one line
// naming it, never crash. HDF5 reads files, so each input goes through one.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "record_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string file = "/tmp/mobb_record_fuzz_" + std::to_string(getpid()) + ".h5";
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    try {
        mobb::crowd::read_h5_record(file);
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        if (m.rfind(file + ": ", 0) != 0 || m.find('\n') != std::string::npos) __builtin_trap();
    }
    return 0;
}
