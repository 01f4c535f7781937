// What an agent's look-aheads learned of the time to go (the look-ahead: rules/look_ahead.h), kept with
// the agent from one choice point to the next. Private to src/crowd.
#pragma once
#include <cstdint>
#include <vector>

namespace mobb::crowd {

/// One agent's learned times to go (LookAhead::learned), kept on a grid of kCell metres: each cell the
/// largest learned, so the search's estimate of a place only rises where the agent found it worse than
/// it looked - a local minimum it waits in (a wall of standing agents between it and its goal) fills
/// up until another way scores better.
class LearnedCost {
public:
    static constexpr double kCell = 0.5;  // metres: about an agent's width
    /// Seconds learned at (x, y); 0 where nothing was.
    double at(double x, double y) const;
    void raise(double x, double y, double seconds);
    /// Forgets everything: what was learned holds for one goal only.
    void clear();

private:
    // A hash table open by linear probing (the search asks at() for every end it scores: a node-based
    // map's bucket division and pointer chase cost 3 % of a run), at most half full.
    struct Slot {
        std::int64_t key = 0;
        double seconds = 0;
        bool used = false;
    };
    static std::int64_t key(double x, double y);
    std::size_t find(std::int64_t key) const;  // its slot, or the empty one where it would go
    std::vector<Slot> slots_;                  // empty, or a power of two of them
    std::size_t used_ = 0;
};

}  // namespace mobb::crowd
