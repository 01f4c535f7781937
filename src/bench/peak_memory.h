// Peak resident memory of this process, per run: the scale workload runs several crowds in one process,
// so it resets the high-water mark before each and reads it after (Linux: /proc/self/clear_refs "5"
// resets VmHWM, since Linux 4.0; getrusage's ru_maxrss cannot be reset).
#pragma once
#include <cstdint>

namespace mobb::bench {

/// Sets the peak to the current resident size. False where the system does not allow it.
bool reset_peak_memory();

/// Bytes: the peak resident size since the last reset (or the process's start); -1 when unknown.
std::int64_t peak_memory_bytes();

}  // namespace mobb::bench
