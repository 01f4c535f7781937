// Broad phase of the crowd: a uniform grid over the ground holding the space-time bounding boxes of
// the clips agents have committed to, so a candidate clip is queried only against clips that can be near.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mobb::crowd {

/// Axis-aligned box in space-time: ground rectangle (metres) and global frames [f0, f1).
struct SpaceTimeBox {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    std::int64_t f0 = 0, f1 = 0;

    bool overlaps(const SpaceTimeBox& o) const {
        return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1 && f0 < o.f1 && o.f0 < f1;
    }
};

/// Uniform grid of square cells (unbounded: cells are hashed, agents may leave the world). Items are
/// caller-chosen ids with an owner (the agent): queries skip the asker's own items.
class BroadPhase {
public:
    explicit BroadPhase(double cell = 4.0);

    void insert(int id, int owner, const SpaceTimeBox& box);
    void remove(int id);
    /// Ids of items of other owners whose boxes overlap `box`, ascending (deterministic).
    void query(const SpaceTimeBox& box, int owner, std::vector<int>& out);
    std::size_t size() const { return live_; }

private:
    struct Item {
        SpaceTimeBox box;
        int owner = -1;
        bool live = false;
    };
    template <class F>
    void cells(const SpaceTimeBox& box, F&& f) const;
    static std::uint64_t key(std::int64_t ix, std::int64_t iy) {
        return (std::uint64_t(ix) << 32) ^ (std::uint64_t(iy) & 0xffffffffull);
    }

    double cell_;
    std::unordered_map<std::uint64_t, std::vector<int>> grid_;
    std::vector<Item> items_;
    std::vector<std::uint32_t> stamp_;
    std::uint32_t query_ = 0;
    std::size_t live_ = 0;
};

}  // namespace mobb::crowd
