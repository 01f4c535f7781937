// The median of a sample, for timings (medians over repeated passes) and robust summaries.
#pragma once
#include <vector>

namespace mobb::util {

/// The middle value of `v` (the mean of the two middle values for an even count); 0 when empty.
double median(std::vector<double> v);

}  // namespace mobb::util
