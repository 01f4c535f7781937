// What an agent's look-aheads learned of the time to go (the look-ahead: rules/look_ahead.h), kept with
// the agent from one choice point to the next. Private to src/crowd.
#pragma once
#include <cstdint>
#include <unordered_map>

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
    void clear() { value_.clear(); }

private:
    static std::int64_t key(double x, double y);
    std::unordered_map<std::int64_t, double> value_;
};

}  // namespace mobb::crowd
