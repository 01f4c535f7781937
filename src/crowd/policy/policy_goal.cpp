// Goal-directed agents: candidates ranked by an estimate of the time to the goal from where they end -
// the clip's own duration, the path length to the goal around the obstacles (a navigation field per
// goal) at walking speed, the turn still needed to face down that path - plus a cost for ending close to
// where the neighbours will be, and, where agents come the other way through a door or down a corridor,
// one for ending in the lane of one nearer the door (letting through: LetThroughTuning) and one for
// ending left of those coming (keeping right: KeepRightTuning; both read policy/passage.h), and one for
// ending beside a wall facing into it (facing along walls: FaceAlongWallsTuning). Clips that stand idle
// come last. An agent that could not move on for a few choice points tries its candidates in random order
// instead, which breaks the deadlocks of agents meeting head-on. Within the goal radius the agent stops:
// standing idle first.
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
#include "policy/walls_ahead.h"

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
        const FaceAlongWallsTuning& fa = c.tuning.face_along_walls;
        // the turn, crowding and facing a wall add no less than 0
        bounded_ = k.turning > 0 && k.crowding >= 0 && k.personal >= 0 && !(fa.on && fa.cost < 0);
        // sqrt of a rounded square is the number itself for a number >= 0 whose square neither overflows nor
        // underflows (binary floating point, rounding to nearest): tested rather than assumed of the tuning.
        far_adds_zero_ = std::sqrt(k.personal * k.personal) == k.personal && std::isfinite(k.crowding);
        for (const auto& g : c.goals) fields_.try_emplace(g, grid_, g);  // one field per distinct goal, built once
        const LetThroughTuning& lt = c.tuning.let_through;
        lets_through_ = lt.on && !c.world.obstacles.empty();
        keeps_right_ = c.tuning.keep_right.on && (c.world.walls || !c.world.obstacles.empty());
        if (lets_through_ || keeps_right_) passages_.emplace(c.world, lt.narrow, lt.reach, grid_.cell);
        if (fa.on && (c.world.walls || !c.world.obstacles.empty()))
            walls_ahead_.emplace(c.world, c.stand_clearance, c.turn_clearance, grid_.cell);
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
    // The lane ahead of an agent the site lets through (LetThroughTuning): from `at` along (cos, sin).
    struct Lane {
        double x, y, cos, sin;
    };
    // Keeping right (KeepRightTuning): ends left of `line` metres along `left` from `from` cost.
    struct KeepRight {
        double from_x = 0, from_y = 0, left_x = 0, left_y = 0;
        double line = 1e300;  // none: no one to keep right of
        double cost = 0;      // seconds per metre left of the line: KeepRightTuning::cost, or open_cost
    };
    // What seconds() reads of a site, worked out once for the many ends it scores: the goal's field, where
    // the neighbours it keeps away from will be (not those it follows), in the site's order, and the lanes
    // and the line it keeps out of.
    struct Around {
        const NavField* field = nullptr;
        NearPoints kept_from;
        std::vector<Lane> let_through;
        KeepRight keep_right;
    };
    Around around(const ChoiceSite& site) const {
        std::vector<std::array<double, 2>> kept_from;
        for (const Neighbour& n : site.neighbours)
            if (!goes_my_way(site, n)) kept_from.push_back(n.at);
        const NavField* field = &fields_.at(*site.goal);
        return {field, NearPoints(std::move(kept_from), tuning_.goal.personal), lanes_let_through(site, *field),
                keep_right_of(site, *field)};
    }

    // Whether neighbour `n` goes the other way to the site's, its way and the site's both read where it is
    // (agents converging on a door along its wall from either side head opposite ways, but go the same way
    // through it); `its_way` gets its way.
    bool oncoming(const ChoiceSite& site, const NavField& field, const Neighbour& n, double& its_way) const {
        if (!n.goal || *n.goal == *site.goal) return false;
        its_way = fields_.at(*n.goal).downhill(n.at[0], n.at[1]);
        return std::abs(wrap_angle(its_way - field.downhill(n.at[0], n.at[1]))) >= tuning_.let_through.oncoming;
    }

    // Keeping right: the line right of the oncoming neighbours ahead on the site's line (the rightmost of
    // their lines), at its cost in a corridor or a door, at the open cost elsewhere.
    KeepRight keep_right_of(const ChoiceSite& site, const NavField& field) const {
        KeepRight k;
        const KeepRightTuning& t = tuning_.keep_right;
        if (!keeps_right_) return k;
        const double way = field.downhill(site.base.x, site.base.y);
        k.cost = passages_->across(site.base.x, site.base.y, way, t.corridor) < t.corridor ? t.cost : t.open_cost;
        if (k.cost <= 0) return k;
        k.from_x = site.base.x, k.from_y = site.base.y, k.left_x = -std::sin(way), k.left_y = std::cos(way);
        std::vector<int> streaming;  // the oncoming agents in the window ahead
        double line = k.line;
        for (const Neighbour& n : site.neighbours) {
            const double dx = n.at[0] - k.from_x, dy = n.at[1] - k.from_y;
            const double along = dx * k.left_y - dy * k.left_x, aside = dx * k.left_x + dy * k.left_y;
            double its_way = 0;
            if (!(along > 0 && along <= t.ahead) || !oncoming(site, field, n, its_way)) continue;
            if (std::find(streaming.begin(), streaming.end(), n.agent) == streaming.end()) streaming.push_back(n.agent);
            if (std::abs(aside) < t.offset) line = std::min(line, aside - t.offset);
        }
        if (int(streaming.size()) >= t.stream) k.line = line;
        return k;
    }

    // Seconds an end costs for lying left of the keep-right line.
    double left_of_line(const Around& a, const Placement& end) const {
        const KeepRight& k = a.keep_right;
        const double aside = (end.x - k.from_x) * k.left_x + (end.y - k.from_y) * k.left_y;
        return aside > k.line ? k.cost * (aside - k.line) : 0.0;
    }

    // Letting through: the lanes ahead of the neighbours coming the other way that are nearer a passage
    // than the site, when the site is near one.
    std::vector<Lane> lanes_let_through(const ChoiceSite& site, const NavField& field) const {
        std::vector<Lane> lanes;
        const LetThroughTuning& k = tuning_.let_through;
        if (!lets_through_ || !passages_->any()) return lanes;
        const double mine = passages_->distance(site.base.x, site.base.y);
        if (mine >= k.reach) return lanes;
        for (const Neighbour& n : site.neighbours) {
            double its_way = 0;
            if (passages_->distance(n.at[0], n.at[1]) < mine && oncoming(site, field, n, its_way))
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
        return crowded(a, end, distance / k.walking + turn / k.turning) + in_lanes(a, end) + left_of_line(a, end) +
               facing_wall(end);
    }

    // Seconds an end costs for facing into a wall it stands beside.
    double facing_wall(const Placement& end) const {
        const FaceAlongWallsTuning& k = tuning_.face_along_walls;
        return walls_ahead_ && walls_ahead_->facing_wall(end, k.ahead) ? k.cost : 0.0;
    }

    // seconds() less the turn: no more than it, each term added being no less than 0 (bounded_), and
    // without the slope's four distances and its atan2.
    double seconds_bound(const Around& a, const Placement& end) const {
        const double distance = a.field->distance(end.x, end.y);
        const GoalTuning& k = tuning_.goal;
        if (distance < stop_radius_) return distance / k.walking;
        return crowded(a, end, distance / k.walking) + in_lanes(a, end) + left_of_line(a, end);
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
    bool lets_through_;                      // LetThroughTuning on, and obstacles in the world
    bool keeps_right_;                       // KeepRightTuning on, and walls or obstacles
    std::optional<PassageMap> passages_;     // when either
    std::optional<WallsAhead> walls_ahead_;  // FaceAlongWallsTuning on, and walls or obstacles
};

}  // namespace

std::unique_ptr<Policy> goal_policy(const PolicyContext& context) { return std::make_unique<GoalPolicy>(context); }

}  // namespace mobb::crowd
