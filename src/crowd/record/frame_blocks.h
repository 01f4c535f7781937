// How a streamed record's frames are grouped: the blocks the stream hands to its sink and the HDF5
// samples' chunks. Private to src/crowd.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace mobb::crowd {

/// Frames per block of a streamed record: about 64 k disks (2 MB) a block, 1 to 256 frames (6 frames at
/// 10,000 agents). The HDF5 samples are chunked by the same blocks.
inline std::int64_t block_frames(std::size_t agents) {
    return std::int64_t(std::clamp<std::size_t>(65536 / std::max<std::size_t>(1, agents), 1, 256));
}

}  // namespace mobb::crowd
