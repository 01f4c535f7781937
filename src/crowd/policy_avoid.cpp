// Wandering without collisions: the candidates in the choice point's random order, except that walking
// clips come before slow ones (starting, stopping) and those before clips that stay in place (so agents
// keep walking while they can), and walking clips heading for a wall after those heading into the open
// (a bias toward the interior that turns agents early, a few degrees per clip).
#include <algorithm>
#include <cmath>
#include <utility>

#include "mobb/crowd/policy.h"

namespace mobb::crowd {

namespace {

class AvoidPolicy : public Policy {
public:
    explicit AvoidPolicy(const PolicyContext& c) : graph_(c.graph), world_(c.world) {
        for (int k = 0; k < int(graph_.clips.size()); ++k) kinds_.push_back(kind_of(graph_.clips[std::size_t(k)], k));
    }

    Selection kind() const override { return Selection::Avoid; }

    void order(const ChoiceSite& site, std::vector<int>& candidates) const override {
        const Rigid2 m = Rigid2::of(site.base);
        std::vector<std::pair<int, int>> ranked;  // (rank, clip), in the stream's order
        for (int c : candidates) ranked.emplace_back(rank(site, m, c), c);
        std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t k = 0; k < ranked.size(); ++k) candidates[k] = ranked[k].second;
    }

private:
    static constexpr double kOpenAhead = 5.0;  // metres of ground ahead of a clip's end: "in the open"

    // 0: walks and keeps going into the open; 1: walks toward a wall; 2: slow (starts, stops); 3: stays.
    int rank(const ChoiceSite& site, const Rigid2& m, int clip) const {
        const ClipKind kind = kinds_[std::size_t(clip)];
        if (kind == ClipKind::InPlace || kind == ClipKind::Idle) return 3;
        if (kind == ClipKind::Slow) return 2;
        return ahead(site.base, graph_.next(site.base, m, clip)) < kOpenAhead ? 1 : 0;
    }

    // How far the agent could go on in the direction it moved from `from` to `to` before leaving the world.
    double ahead(const Placement& from, const Placement& to) const {
        const double dx = to.x - from.x, dy = to.y - from.y, len = std::sqrt(dx * dx + dy * dy);
        if (len == 0) return 0;
        const double ux = dx / len, uy = dy / len;
        double t = 1e300;
        if (ux > 0) t = std::min(t, (world_.x1 - to.x) / ux);
        if (ux < 0) t = std::min(t, (world_.x0 - to.x) / ux);
        if (uy > 0) t = std::min(t, (world_.y1 - to.y) / uy);
        if (uy < 0) t = std::min(t, (world_.y0 - to.y) / uy);
        return std::max(0.0, t);
    }

    const MotionGraph& graph_;
    const World& world_;
    std::vector<ClipKind> kinds_;  // per clip
};

}  // namespace

std::unique_ptr<Policy> avoid_policy(const PolicyContext& context) { return std::make_unique<AvoidPolicy>(context); }

}  // namespace mobb::crowd
