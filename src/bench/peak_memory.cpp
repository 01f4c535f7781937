#include "peak_memory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace mobb::bench {

bool reset_peak_memory() {
    std::ofstream f("/proc/self/clear_refs");
    return bool(f << "5" << std::flush);
}

std::int64_t peak_memory_bytes() {
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("VmHWM:", 0) == 0) {
            std::int64_t kb = -1;
            std::istringstream(line.substr(6)) >> kb;
            return kb < 0 ? -1 : kb * 1024;
        }
    return -1;
}

}  // namespace mobb::bench
