// What the benchmark tables note about the machine they ran on.
#pragma once
#include <map>
#include <string>

namespace mobb::bench {

/// Adds "cpu" (the model name from /proc/cpuinfo, or "unknown") and "timing" (how rows were timed).
void add_machine_notes(std::map<std::string, std::string>& notes);

/// The processor's model name from /proc/cpuinfo, or "unknown".
std::string cpu_name();

}  // namespace mobb::bench
