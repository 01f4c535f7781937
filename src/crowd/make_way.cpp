// Making way (CrowdTuning::make_way): an agent that could not move on for a few choice points asks the
// agents near it for the way it wants (Policy::way: a few metres down its path); an agent it outranks -
// it set off for its goal earlier, or at once with a lower id: the priority of Okumura et al.'s PIBT
// (2019), which grows until the goal is reached - keeps its
// clips' ends clear of that way for a few seconds (the policy counts it in its time to go), so it steps
// aside before the asking agent comes. Two agents meeting in a door both stand: neither walks, so neither
// can take the right of way (right_of_way.cpp), and each waits for the other; this lets one through.
#include <algorithm>
#include <cmath>

#include "choice.h"

namespace mobb::crowd {

namespace {

/// Whether agent `a` goes before agent `b`: it has headed for its goal longer (it set off earlier), or as
/// long with a lower id. As in PIBT, the priority grows until the goal is reached, so it never flips
/// between two agents waiting for each other.
bool outranks(const Agent& a, int a_id, const Agent& b, int b_id) {
    return a.heading_since < b.heading_since || (a.heading_since == b.heading_since && a_id < b_id);
}

}  // namespace

// The ways asked, and still asked this frame, by the agents whose pieces are near (near_) and who
// outrank this one, as segments of the site.
void Choice::ways_to_make(const CrowdState& s, ChoiceSite& site) {
    const CrowdTuning& t = s.options.tuning;
    const Agent& me = s.agents[std::size_t(agent_)];
    // Only an agent stuck itself: one making progress is not waiting for anyone (a deadlock is two agents
    // each waiting for the other).
    if (!t.make_way || !site.goal || double(frame_ - me.progress_frame) * s.graph.dt() < t.make_way_after) return;
    // Only ways against this agent's own: one behind it in a queue going its way waits its turn.
    const std::vector<std::array<double, 2>> mine = s.policy.way(site, 1.0);
    const double mx = mine.size() > 1 ? mine.back()[0] - mine.front()[0] : 0.0;
    const double my = mine.size() > 1 ? mine.back()[1] - mine.front()[1] : 0.0;
    asking_.clear();
    for (int id : near_) {
        const int o = s.pieces[std::size_t(id)].agent;
        if (o < 0 || o == agent_ || std::find(asking_.begin(), asking_.end(), o) != asking_.end()) continue;
        asking_.push_back(o);
        const Agent& other = s.agents[std::size_t(o)];
        if (other.way_until < frame_ || !outranks(other, o, me, agent_)) continue;
        const auto& w = other.way;
        if (w.size() < 2) continue;
        if ((w.back()[0] - w.front()[0]) * mx + (w.back()[1] - w.front()[1]) * my > 0) continue;
        for (std::size_t k = 0; k + 1 < other.way.size(); ++k)
            site.make_way.push_back({other.way[k][0], other.way[k][1], other.way[k + 1][0], other.way[k + 1][1]});
    }
}

// The time to go from here, and the way this agent asks for when it made no progress for make_way_after
// seconds and is not stopping.
void Choice::ask_way(const CrowdState& s, const ChoiceSite& site) {
    way_.clear();
    const CrowdTuning& t = s.options.tuning;
    if (!t.make_way || !site.goal) return;
    ChoiceSite alone = site;  // the progress is the path's, whoever stands near
    alone.neighbours.clear();
    alone.make_way.clear();
    to_go_ = s.policy.to_go(alone, site.base);
    const Agent& a = s.agents[std::size_t(agent_)];
    if (site.arrived || double(frame_ - a.progress_frame) * s.graph.dt() < t.make_way_after) return;
    way_ = s.policy.way(site, t.make_way_length);
}

}  // namespace mobb::crowd
