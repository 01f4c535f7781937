// libFuzzer entry point for the HDF5 crowd-record readers (ours: src/crowd/record/record_h5_read.cpp, which reads
// a file whole, record_h5_window.cpp, which reads it in parts - the viewer's and Python's way - h5.cpp and
// the JSON reader's checks; libhdf5 itself is not instrumented): any file must read or throw one line
// naming it, never crash. HDF5 reads files, so each input goes through one.
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "mobb/crowd/record/record_reader.h"
#include "record/record_json.h"

namespace {

// Every part the viewer and Python ask for: the header with the clip table, the first and last frames
// (all agents, then a range), the choice points of the first frames, the first and last choice points
// whole, the fallbacks.
void read_in_parts(const std::string& file) {
    const auto r = mobb::crowd::open_record(file, std::size_t(1) << 20);
    const std::int64_t frames = r->header().frames;  // and the clip table
    r->samples(0, 2);
    r->samples(frames - 2, frames, {1, 3});
    const auto [lo, hi] = r->choice_rows(0, 30);
    r->summaries(lo, std::min(hi, lo + 1000));
    if (r->choice_count() > 0) {
        r->choice(0);
        r->choice(r->choice_count() - 1);
    }
    r->fallbacks();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string file = "/tmp/mobb_record_fuzz_" + std::to_string(getpid()) + ".h5";
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    for (const auto read : {+[](const std::string& name) { mobb::crowd::read_h5_record(name); }, &read_in_parts}) {
        try {
            read(file);
        } catch (const std::runtime_error& e) {
            const std::string m = e.what();
            if (m.rfind(file + ": ", 0) != 0 || m.find('\n') != std::string::npos) __builtin_trap();
        }
    }
    return 0;
}
