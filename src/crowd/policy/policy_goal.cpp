// Goal-directed agents: candidates ranked by an estimate of the time to the goal from where they end -
// the clip's own duration, the path length to the goal around the obstacles (a navigation field per
// goal) at walking speed, the turn still needed to face down that path - plus a cost for ending close to
// where the neighbours will be, and one for ending in the lane of a neighbour coming through a passage
// the other way (letting through: LetThroughTuning, policy/passage.h). Clips that stand idle come last. An agent that could not move on for a
// few choice points tries its candidates in random order instead, which breaks the deadlocks of agents
// meeting head-on. Within the goal radius the agent stops: standing idle first.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <utility>

#include "mobb/core/angle.h"
#include "mobb/crowd/policy/policy.h"
#include "policy/follow.h"
#include "policy/nav_field.h"
#include "policy/near_points.h"
#include "policy/passage.h"

namespace mobb::crowd {

namespace {

std::size_t distinct_goals(std::vector<std::array<double, 2>> goals) {
    std::sort(goals.begin(), goals.end());
    return std::size_t(std::unique(goals.begin(), goals.end()) - goals.begin());
}

class GoalPolicy : public Policy {
public:
    explicit GoalPolicy(const PolicyContext& c)
        : graph_(c.graph),
          tuning_(c.tuning),
          radius_(c.goal_radius),
          grid_(c.world, c.tuning.goal.nav_clearance, nav_cell(c.world, distinct_goals(c.goals))) {
        kinds_ = kinds_of(graph_);
        // An agent stops by standing where its clip ends, then sways within its idle clips' reach (of their
        // disks' centres from the root where the idle clip starts, the origin): it stops that much inside the
        // goal radius so that it stays within it to the end.
        double sway = 0;
        for (int k = 0; k < int(graph_.clips.size()); ++k) {
            if (kinds_[std::size_t(k)] != ClipKind::Idle) continue;
            const auto& samples = graph_.clips[std::size_t(k)].path.samples;
            for (const Sample& x : samples) sway = std::max(sway, std::hypot(x.x, x.y));
        }
        stop_radius_ = radius_ - sway;
        const GoalTuning& k = c.tuning.goal;
        bounded_ = k.turning > 0 && k.crowding >= 0 && k.personal >= 0;  // the turn and crowding add no less than 0
        // sqrt of a rounded square is the number itself for a number >= 0 whose square neither overflows nor
        // underflows (binary floating point, rounding to nearest): tested rather than assumed of the tuning.
        far_adds_zero_ = std::sqrt(k.personal * k.personal) == k.personal && std::isfinite(k.crowding);
        for (const auto& g : c.goals) fields_.try_emplace(g, grid_, g);  // one field per distinct goal, built once
        const LetThroughTuning& lt = c.tuning.let_through;
        if (lt.on && !c.world.obstacles.empty()) passages_.emplace(c.world, lt.narrow, lt.reach, grid_.cell);
    }

    Selection kind() const override { return Selection::Goal; }
    bool stops_near_walls() const override { return true; }

    void order(const ChoiceSite& site, std::vector<int>& candidates) const override {
        if (!site.goal) return;
        const Rigid2 m = Rigid2::of(site.base);
        const Around around_site = site.arrived ? Around{} : around(site);
        std::vector<std::pair<double, int>> scored;
        scored.reserve(candidates.size());
        for (int c : candidates)
            scored.emplace_back(site.arrived ? stop_cost(site, m, c) : cost(site, around_site, m, c), c);
        std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t k = 0; k < scored.size(); ++k) candidates[k] = scored[k].second;
    }

    double neighbourhood() const override { return tuning_.goal.neighbourhood; }

    // A stuck agent (GoalTuning::patience) and one at its goal order their candidates alone.
    int horizon(const ChoiceSite& site) const override {
        return site.goal && !site.arrived && site.choices_waited < tuning_.goal.patience ? tuning_.goal.horizon : 0;
    }

    double to_go(const ChoiceSite& site, const Placement& end) const override { return seconds(around(site), end); }

    Estimate estimate(const ChoiceSite& site) const override {
        const auto a = std::make_shared<const Around>(around(site));
        Estimate e{[this, a](const Placement& end) { return seconds(*a, end); }, {}};
        if (bounded_) e.bound = [this, a](const Placement& end) { return seconds_bound(*a, end); };
        return e;
    }

    std::optional<double> heading(const ChoiceSite& site) const override {
        if (!site.goal) return std::nullopt;
        return fields_.at(*site.goal).downhill(site.base.x, site.base.y);
    }

    // Agents standing at their goals are obstacles for the others' paths.
    void settled(double x, double y, double r) override {
        grid_.block_disk(x, y, r);
        for (auto& [goal, field] : fields_) field.block(grid_);
    }

    bool arrived(const ChoiceSite& site) const override {
        return site.goal && site.stops &&
               std::hypot(site.base.x - (*site.goal)[0], site.base.y - (*site.goal)[1]) < stop_radius_;
    }

private:
    // What seconds() reads of a site, worked out once for the many ends it scores: the goal's field, and
    // where the neighbours it keeps away from will be (not those it follows), in the site's order.
    // The lane ahead of an agent the site lets through (LetThroughTuning): from `at` along (cos, sin).
    struct Lane {
        double x, y, cos, sin;
    };
    struct Around {
        const NavField* field = nullptr;
        NearPoints kept_from;
        std::vector<Lane> let_through;
    };
    Around around(const ChoiceSite& site) const {
        std::vector<std::array<double, 2>> kept_from;
        for (const Neighbour& n : site.neighbours)
            if (!goes_my_way(site, n)) kept_from.push_back(n.at);
        const NavField* field = &fields_.at(*site.goal);
        return {field, NearPoints(std::move(kept_from), tuning_.goal.personal), lanes_let_through(site, *field)};
    }

    // Letting through: the lanes ahead of the neighbours coming the other way that are nearer a passage
    // than the site, when the site is near one.
    std::vector<Lane> lanes_let_through(const ChoiceSite& site, const NavField& field) const {
        std::vector<Lane> lanes;
        const LetThroughTuning& k = tuning_.let_through;
        if (!passages_ || !passages_->any()) return lanes;
        const double mine = passages_->distance(site.base.x, site.base.y);
        if (mine >= k.reach) return lanes;
        for (const Neighbour& n : site.neighbours) {
            if (!n.goal || *n.goal == *site.goal || passages_->distance(n.at[0], n.at[1]) >= mine) continue;
            // Both ways read where the other is: agents converging on a door from either side along its
            // wall head for it in opposite directions, but go the same way through it.
            const double its_way = fields_.at(*n.goal).downhill(n.at[0], n.at[1]);
            if (std::abs(wrap_angle(its_way - field.downhill(n.at[0], n.at[1]))) >= k.oncoming)
                lanes.push_back({n.at[0], n.at[1], std::cos(its_way), std::sin(its_way)});
        }
        return lanes;
    }

    // Seconds an end costs in the lanes of those it lets through: the most of any lane, `cost` on a lane's
    // middle falling to 0 at its sides.
    double in_lanes(const Around& a, const Placement& end) const {
        const LetThroughTuning& k = tuning_.let_through;
        double most = 0;
        for (const Lane& l : a.let_through) {
            const double dx = end.x - l.x, dy = end.y - l.y;
            const double along = dx * l.cos + dy * l.sin, aside = std::abs(dy * l.cos - dx * l.sin);
            if (along >= 0 && along <= k.lane_length && aside < k.lane_width)
                most = std::max(most, k.cost * (1 - aside / k.lane_width));
        }
        return most;
    }

    // Time to the goal from the clip's end: the path at walking speed, the turn to face down it, plus a
    // cost for ending close to where the neighbours will be. Within the stop radius, the path alone: the
    // agent stops there whichever way it faces and whoever stands near (else ending at the goal facing
    // away, or beside an agent standing at its own goal, would cost more than ending short of it, and an
    // agent could circle its goal for good).
    double seconds(const Around& a, const Placement& end) const {
        const double distance = a.field->distance(end.x, end.y);
        const GoalTuning& k = tuning_.goal;
        if (distance < stop_radius_) return distance / k.walking;
        const double turn = std::abs(wrap_angle(a.field->downhill(end.x, end.y) - end.theta));
        return crowded(a, end, distance / k.walking + turn / k.turning) + in_lanes(a, end);
    }

    // seconds() less the turn: no more than it, each term added being no less than 0 (bounded_), and
    // without the slope's four distances and its atan2.
    double seconds_bound(const Around& a, const Placement& end) const {
        const double distance = a.field->distance(end.x, end.y);
        const GoalTuning& k = tuning_.goal;
        if (distance < stop_radius_) return distance / k.walking;
        return crowded(a, end, distance / k.walking) + in_lanes(a, end);
    }

    // `t` plus the cost of ending `end` close to where the neighbours will be, added in their order.
    double crowded(const Around& a, const Placement& end, double t) const {
        if (far_adds_zero_ && t >= 0 && !std::signbit(t)) return crowding_sum<true>(a, end, t);
        return crowding_sum<false>(a, end, t);
    }

    // kBranchFree: without a branch on the distance, which the listed points pass about half the time. A
    // point no nearer than `personal` then adds crowding * (personal - sqrt(personal^2)) = +-0
    // (far_adds_zero_), which leaves t >= +0 as it is: the same sum as the branch.
    template <bool kBranchFree>
    double crowding_sum(const Around& a, const Placement& end, double t) const {
        const GoalTuning& k = tuning_.goal;
        const double r2 = k.personal * k.personal;
        a.kept_from.near(end.x, end.y, [&](std::size_t i) {
            const std::array<double, 2>& at = a.kept_from.points()[i];
            const double dx = end.x - at[0], dy = end.y - at[1], d2 = dx * dx + dy * dy;  // hypot is slow
            if constexpr (kBranchFree)
                t += k.crowding * (k.personal - std::sqrt(d2 < r2 ? d2 : r2));
            else if (d2 < r2)
                t += k.crowding * (k.personal - std::sqrt(d2));
        });
        return t;
    }

    // Following (CrowdTuning::follow): a leader is one to follow, not to keep away from.
    bool goes_my_way(const ChoiceSite& site, const Neighbour& n) const {
        return site.way && n.facing &&
               follows(*site.way, {site.base.x, site.base.y}, n.at, *n.facing, tuning_.follow.angle);
    }

    // Walking on: the estimated time to the goal; standing idle last. A stuck agent
    // (GoalTuning::patience) keeps the stream's random order instead, clips that move before those
    // in place, which moves it out of the way of the agents it waits for: two agents meeting head-on in a
    // door each step aside or back rather than turn on the spot in front of the other
    // (bench/results/log.md, "Following").
    double cost(const ChoiceSite& site, const Around& a, const Rigid2& m, int c) const {
        const double idle = kinds_[std::size_t(c)] == ClipKind::Idle ? 1e12 : 0.0;
        if (site.choices_waited >= tuning_.goal.patience)
            return idle + (kinds_[std::size_t(c)] == ClipKind::InPlace ? 1e6 : 0.0);
        const Placement end = graph_.next(site.base, m, c);
        return idle + graph_.clips[std::size_t(c)].path.duration() + seconds(a, end);
    }

    // At the goal: standing idle first, then turning in place, then the clips that end nearest to it.
    double stop_cost(const ChoiceSite& site, const Rigid2& m, int c) const {
        const ClipKind kind = kinds_[std::size_t(c)];
        if (kind == ClipKind::Idle) return 0;
        const Placement end = graph_.next(site.base, m, c);
        const double d = std::hypot(end.x - (*site.goal)[0], end.y - (*site.goal)[1]);
        return (kind == ClipKind::InPlace ? 1e3 : 1e6) + d;
    }

    const MotionGraph& graph_;
    const CrowdTuning tuning_;
    std::vector<ClipKind> kinds_;
    double radius_;
    double stop_radius_;  // metres: radius_ less the idle clips' sway
    bool bounded_;        // seconds_bound() is a lower bound of seconds()
    bool far_adds_zero_;  // crowding * (personal - sqrt(personal^2)) is +-0: crowded() sums without a branch
    NavGrid grid_;
    std::map<std::array<double, 2>, NavField> fields_;
    std::optional<PassageMap> passages_;  // with letting through on and obstacles in the world
};

}  // namespace

std::unique_ptr<Policy> goal_policy(const PolicyContext& context) { return std::make_unique<GoalPolicy>(context); }

}  // namespace mobb::crowd
