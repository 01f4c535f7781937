#include "machine.h"

#include <fstream>

namespace mobb::bench {

std::string cpu_name() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

void add_machine_notes(std::map<std::string, std::string>& notes) {
    notes["cpu"] = cpu_name();
    notes["timing"] = "median over timed passes of (pass time / queries); methods interleaved within each pass";
}

}  // namespace mobb::bench
