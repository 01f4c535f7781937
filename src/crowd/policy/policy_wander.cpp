// Wandering without collisions: the candidates in the choice point's random order, except that walking
// clips come before slow ones (starting, stopping) and those before clips that stay in place (so agents
// keep walking while they can), except that slow clips slower than the idle speed (creeping) come last;
// walks heading for a wall come after those heading into the open (a bias toward the interior that turns
// agents early, a few degrees per clip); slow clips the faster first; and near a wall, turns on the spot
// that end facing the open first.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "mobb/crowd/policy/policy.h"
#include "world/planar.h"

namespace mobb::crowd {

namespace {

class WanderPolicy : public Policy {
public:
    explicit WanderPolicy(const PolicyContext& c)
        : graph_(c.graph),
          world_(c.world),
          moving_(c.tuning.moving_speed),
          open_ahead_(c.tuning.wander.open_ahead),
          band_(c.tuning.wander.band),
          bands_(bands_of(c.tuning.wander)) {
        for (int k = 0; k < int(graph_.clips.size()); ++k) {
            const GraphClip& clip = graph_.clips[std::size_t(k)];
            kinds_.push_back(kind_of(clip, k));
            reach_.push_back(std::hypot(clip.exit_x, clip.exit_y));
            farthest_ = std::max(farthest_, reach_.back());
        }
        rank_slower_clips();
    }

    Selection kind() const override { return Selection::Wander; }

    // How many bands of WanderTuning::band fit in its open_ahead; throws std::invalid_argument unless
    // between 1 and a million.
    static int bands_of(const WanderTuning& t) {
        const double bands = t.open_ahead / t.band;
        if (!(t.band > 0) || !(bands >= 1 && bands <= 1e6))
            throw std::invalid_argument(
                "crowd: wander.band must be positive, and wander.open_ahead 1 to a million of it");
        return int(bands);
    }
    bool keeps_standing_gap() const override { return true; }

    // A stable insertion sort by rank: a few dozen candidates, no allocation.
    void order(const ChoiceSite& site, std::vector<int>& candidates) const override {
        const Placement& b = site.base;
        const double wall = std::min({b.x - world_.x0, world_.x1 - b.x, b.y - world_.y0, world_.y1 - b.y});
        if (wall >= open_ahead_ + farthest_ && slower_.size() <= kMaxSlower) return order_in_open(candidates);
        const Rigid2 m = Rigid2::of(b);
        struct Ranked {
            int rank, clip;
        };
        Ranked buffer[256];
        std::vector<Ranked> spill;
        Ranked* ranked = buffer;
        if (candidates.size() > std::size(buffer)) ranked = (spill.resize(candidates.size()), spill.data());
        for (std::size_t k = 0; k < candidates.size(); ++k) {
            const Ranked x{rank(site, m, candidates[k], wall), candidates[k]};
            std::size_t j = k;
            for (; j > 0 && ranked[j - 1].rank > x.rank; --j) ranked[j] = ranked[j - 1];
            ranked[j] = x;
        }
        for (std::size_t k = 0; k < candidates.size(); ++k) candidates[k] = ranked[k].clip;
    }

private:
    // Far from every wall the ranks depend on the clip alone: the walks in their drawn order, then the
    // others in their fixed rank order (each has a rank of its own). The same order as the sort.
    void order_in_open(std::vector<int>& candidates) const {
        int count[kMaxSlower] = {};
        std::size_t walks = 0;
        for (int c : candidates) {
            if (kinds_[std::size_t(c)] != ClipKind::Walk) {
                ++count[slower_rank_[std::size_t(c)] - bands_ - 1];
                continue;
            }
            candidates[walks++] = c;
        }
        for (std::size_t i = 0; i < slower_.size() && walks < candidates.size(); ++i)
            for (int n = count[i]; n > 0; --n) candidates[walks++] = slower_[i];
    }

    static constexpr std::size_t kMaxSlower = 256;  // order_in_open counts them on the stack

    // Clips that do not walk, after every walk: slow ones (starts, stops) that move (moving_) or
    // faster, then those in place, then the slow ones that only creep; each kind the faster first (an
    // agent that must slow down keeps as much of its speed as it can, and one that cannot move turns to
    // find a way out rather than creep along the way it is stuck in).
    void rank_slower_clips() {
        std::vector<int> slower;
        for (int k = 0; k < int(kinds_.size()); ++k)
            if (kinds_[std::size_t(k)] != ClipKind::Walk) slower.push_back(k);
        const auto key = [&](int k) {
            const ClipKind kind = kinds_[std::size_t(k)];
            const double duration = double(graph_.clips[std::size_t(k)].path.size()) * graph_.dt();
            const double speed = reach_[std::size_t(k)] / duration;
            if (kind != ClipKind::Slow) return std::pair{1, -speed};
            return std::pair{speed >= moving_ ? 0 : 2, -speed};
        };
        std::stable_sort(slower.begin(), slower.end(), [&](int a, int b) { return key(a) < key(b); });
        slower_rank_.assign(kinds_.size(), 0);
        for (std::size_t i = 0; i < slower.size(); ++i) slower_rank_[std::size_t(slower[i])] = bands_ + 1 + int(i);
        slower_ = std::move(slower);
    }

    // 0: walks and keeps going into the open; 1 .. bands_: walks toward a wall, the nearer the later;
    // then the slower clips (rank_slower_clips). `wall`: the base's distance to the nearest wall (a clip
    // ending farther than open_ahead_ from every wall is in the open).
    int rank(const ChoiceSite& site, const Rigid2& m, int clip, double wall) const {
        const ClipKind kind = kinds_[std::size_t(clip)];
        if (kind == ClipKind::Slow) return slower_rank_[std::size_t(clip)];
        if (kind != ClipKind::Walk) {
            // Turning on the spot near a wall: facing the open first, so that a walk can follow.
            if (wall - reach_[std::size_t(clip)] >= open_ahead_) return slower_rank_[std::size_t(clip)];
            const Placement end = graph_.next(site.base, m, clip);
            const double room = ahead(end, {end.x + std::cos(end.theta), end.y + std::sin(end.theta), 0, 0});
            return slower_rank_[std::size_t(clip)] + int(kinds_.size()) * band(room);
        }
        if (wall - reach_[std::size_t(clip)] >= open_ahead_) return 0;
        return band(ahead(site.base, graph_.next(site.base, m, clip)));
    }

    // 0 with open_ahead_ metres of room ahead, else 1 .. bands_, the less room the higher.
    int band(double room) const {
        return room >= open_ahead_ ? 0 : 1 + std::min(bands_ - 1, int((open_ahead_ - room) / band_));
    }

    // How far the agent could go on in the direction it moved from `from` to `to` before leaving the world.
    double ahead(const Placement& from, const Placement& to) const {
        const double dx = to.x - from.x, dy = to.y - from.y, len = planar_distance(dx, dy);
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
    const double moving_;           // m/s: CrowdTuning::moving_speed
    const double open_ahead_;       // metres of ground ahead of a clip's end: "in the open" (WanderTuning)
    const double band_;             // metres: walks toward a wall ranked in bands this wide (WanderTuning)
    const int bands_;               // of them, from a wall to open_ahead_
    std::vector<ClipKind> kinds_;   // per clip
    std::vector<double> reach_;     // per clip: metres from its start to its exit
    std::vector<int> slower_rank_;  // per clip that does not walk: its rank
    std::vector<int> slower_;       // the clips that do not walk, by rank
    double farthest_ = 0;           // the largest of them
};

}  // namespace

std::unique_ptr<Policy> wander_policy(const PolicyContext& context) { return std::make_unique<WanderPolicy>(context); }

}  // namespace mobb::crowd
