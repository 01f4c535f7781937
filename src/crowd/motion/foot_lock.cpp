// Foot locking in CrowdPoser (agent_pose.h): a planted foot held where its contact began, the leg bent to
// reach it (two_joint_ik), the hold let go over FootLock::release after the contact; a foot low in a blend
// with no contact pinned (FootLock::pin).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "mobb/crowd/motion/agent_pose.h"

namespace mobb::crowd {

namespace {

glm::dvec3 planted_point(const glm::dvec3& ankle, const glm::dvec3& toe, Plant plant) {
    return plant == Plant::Toe ? toe : ankle;
}

// The smallest rotation that takes unit vector a to unit vector b (Rodrigues), set up once per segment and
// applied to each joint hanging from it.
struct Turn {
    glm::dvec3 k{0.0};
    double s = 0, c = 1;
    bool none = true;  // a and b (anti)parallel: joints are left as they are
    Turn(const glm::dvec3& a, const glm::dvec3& b) {
        const glm::dvec3 axis = glm::cross(a, b);
        s = glm::length(axis);
        c = glm::dot(a, b);
        none = s < 1e-12;
        if (!none) k = axis / s;
    }
    glm::dvec3 operator()(const glm::dvec3& v) const {
        return none ? v : v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
    }
};

glm::dvec3 unit(const glm::dvec3& v) {
    const double l = glm::length(v);
    return l > 1e-12 ? v / l : glm::dvec3(0.0);
}

// The leg of `out` moved to the IK's knee and ankle: joints hanging from the thigh and shin turn with them,
// those of the foot move with the ankle (the foot keeps its orientation in the pose).
void bend_leg(const RigLeg& leg, const LegSolve& s, std::vector<glm::dvec3>& out) {
    const glm::dvec3 hip = out[std::size_t(leg.hip)], knee = out[std::size_t(leg.knee)],
                     ankle = out[std::size_t(leg.ankle)];
    const Turn thigh(unit(knee - hip), unit(s.knee - hip)), shin(unit(ankle - knee), unit(s.ankle - s.knee));
    const glm::dvec3 moved = s.ankle - ankle, bent_knee = s.knee;
    for (const auto& [j, segment] : leg.hanging) {
        glm::dvec3& q = out[std::size_t(j)];
        if (segment == 3)
            q += moved;
        else if (segment == 2)
            q = bent_knee + shin(q - knee);
        else
            q = hip + thigh(q - hip);
    }
    out[std::size_t(leg.knee)] = s.knee;
    out[std::size_t(leg.ankle)] = s.ankle;
}

// The foot is up at samples [first, first + frames) of the track.
bool up_from(const FootTrack& t, int first, int frames) {
    if (first < 0 || frames < 0 || std::size_t(first) + std::size_t(frames) > t.plant.size()) return false;
    for (int i = first; i < first + frames; ++i)
        if (t.plant[std::size_t(i)] != Plant::Free) return false;
    return true;
}

}  // namespace

Plant CrowdPoser::plant_at(int agent, std::int64_t k, int foot, bool carry) {
    AgentClipAt at;
    return played_at(agent, k, at) ? plant_in(at, k, foot, carry) : Plant::Free;
}

Plant CrowdPoser::plant_in(const AgentClipAt& at, std::int64_t k, int foot, bool carry) {
    const GraphClip& gc = sources_->graph().clips[std::size_t(at.placed->clip)];
    const FootTrack& t = sources_->get(gc.source).feet[std::size_t(foot)];
    const std::size_t i = std::size_t(at.sample);
    if (i >= t.plant.size()) return Plant::Free;
    if (t.plant[i] != Plant::Free || !carry || t.run_begin[i] > gc.first) return t.plant[i];
    return carried_plant(at, k, foot);
}

bool CrowdPoser::in_blend(std::int64_t i) const { return i < blend_frames_; }

Plant CrowdPoser::carried_plant(const AgentClipAt& at, std::int64_t k, int foot) {
    return at.index > 0 && in_blend(k - at.placed->start) ? carried_into(at, foot) : Plant::Free;
}

Plant CrowdPoser::carried_into(const AgentClipAt& at, int foot) {
    CarryCache& c = carry_[std::size_t(foot)];
    if (c.placed == at.placed) return c.plant;  // the clip of the last call: every frame of a blend asks
    c = {at.placed, Plant::Free};
    if (at.index == 0) return c.plant;
    const MotionGraph& g = sources_->graph();
    const GraphClip& gc = g.clips[std::size_t(at.placed->clip)];
    // The new clip keeps the foot up through the blend and the release after it, so the carried contact
    // lets go before the clip's own next one begins (one contact never stands in two places).
    const int up = int(blend_frames_) + release_frames();
    if (!up_from(sources_->get(gc.source).feet[std::size_t(foot)], gc.first, up)) return c.plant;
    if (!blends_into(at)) return c.plant;
    const GraphClip& gp = g.clips[std::size_t(at.placed[-1].clip)];
    const FootTrack& t = sources_->get(gp.source).feet[std::size_t(foot)];
    if (gp.exit <= gp.first || std::size_t(gp.exit) >= t.plant.size()) return c.plant;
    // Planted at its last frame and at its exit, the pose the blend eases out of.
    if (t.plant[std::size_t(gp.exit)] != Plant::Free) c.plant = t.plant[std::size_t(gp.exit - 1)];
    return c.plant;
}

bool CrowdPoser::free_for(int agent, std::int64_t k, int foot, int frames) {
    // Frame k is the one pose() poses, and the clip it plays has had the foot free for `frames` frames,
    // none of them carried from the clip before.
    if (agent != posed_agent_ || k != posed_frame_) return false;
    const GraphClip& gc = sources_->graph().clips[std::size_t(posed_.placed->clip)];
    const FootTrack& t = sources_->get(gc.source).feet[std::size_t(foot)];
    const int i = posed_.sample;
    return std::size_t(i) < t.plant.size() && t.plant[std::size_t(i)] == Plant::Free &&
           i - frames >= std::max(t.run_begin[std::size_t(i)], gc.first) &&
           (!lock_.carry || t.run_begin[std::size_t(i)] > gc.first || !in_blend(i - frames - gc.first) ||
            carried_into(posed_, foot) == Plant::Free);
}

bool CrowdPoser::foot_free(int agent, std::int64_t k, int foot, FootFree& out) {
    if (!free_pose(agent, k, foot_[std::size_t(foot)], d_, e_)) return false;
    const RigLeg& leg = legs_[std::size_t(foot)];
    out = {d_[std::size_t(leg.hip)],
           d_[std::size_t(leg.knee)],
           d_[std::size_t(leg.ankle)],
           d_[std::size_t(leg.toe)],
           d_[0],
           envelope(agent, k)};
    return true;
}

void CrowdPoser::glide_towards(glm::dvec3& point, const glm::dvec3& own) const {
    // On the ground at most FootLock::glide, in height at most FootLock::glide_height.
    const double dx = own.x - point.x, dy = own.y - point.y, d = std::sqrt(dx * dx + dy * dy);
    const double most = lock_.glide * record_.dt, f = d > most ? most / d : 1.0;
    const double rise = lock_.glide_height * record_.dt;
    point += glm::dvec3(dx * f, dy * f, std::clamp(own.z - point.z, -rise, rise));
}

void CrowdPoser::hold_step(Hold& h, const FootFree& q, Plant plant, bool first, const glm::dvec3* own,
                           const glm::dvec3& from) const {
    // The first planted point stays where it came down (`from` the free pose's); a next one where the hold
    // puts it then. Either glides towards the clip's own (FootLock::glide).
    if (first)
        h.point = planted_point(q.ankle, q.toe, plant) + from;
    else if (plant != h.plant)
        h.point += planted_point(q.ankle, q.toe, plant) - planted_point(q.ankle, q.toe, h.plant);
    if (own && !first) glide_towards(h.point, *own);
    h.plant = plant;
    h.ankle = q.ankle;
    h.target = h.point + (q.ankle - planted_point(q.ankle, q.toe, plant));
    // Beyond the leg's reach (or the disk) the planted point is lifted or dragged along.
    const glm::dvec3 held = within_reach(h.target, q);
    h.dragged = glm::length(held - h.target);
    h.point += held - h.target;
    h.target = held;
    h.toe = held + (q.toe - q.ankle);
}

glm::dvec3 CrowdPoser::within_reach(const glm::dvec3& target, const FootFree& q) const {
    // The leg stretched at most to lock_.reach of its length (or the free pose's own stretch): the target
    // raised to where the leg reaches it (FootLock::lift), else towards the hip; then on the ground inside
    // the disk the collision answers used, towards its centre.
    const double leg = glm::length(q.knee - q.hip) + glm::length(q.ankle - q.knee);
    const double limit = std::min(leg, std::max(glm::length(q.ankle - q.hip), lock_.reach * leg));
    glm::dvec3 out = target;
    const double gx = target.x - q.hip.x, gy = target.y - q.hip.y, ground = std::sqrt(gx * gx + gy * gy);
    if (lock_.lift && ground < limit) out.z = std::max(out.z, q.hip.z - std::sqrt(limit * limit - ground * ground));
    const double d = glm::length(out - q.hip);
    if (d > limit) out = q.hip + (out - q.hip) * (limit / d);
    const double cx = q.root.x + q.disk.offset.x, cy = q.root.y + q.disk.offset.y;
    const double dx = out.x - cx, dy = out.y - cy, from_centre = std::sqrt(dx * dx + dy * dy);
    if (from_centre > q.disk.radius) {
        const double f = q.disk.radius * (1 - 1e-12) / from_centre;
        out = {cx + dx * f, cy + dy * f, out.z};
    }
    return out;
}

const CrowdPoser::Hold* CrowdPoser::contact_target(int agent, std::int64_t k, int foot, Plant plant,
                                                   const FootFree* free) {
    if (holds_.empty()) holds_.resize(record_.tracks.size());
    Hold& h = holds_[std::size_t(agent)][std::size_t(foot)];
    // Frame k - 1 was held: frame k is in the same contact, one step on (a window may have moved since).
    if (!window_ && h.start >= 0 && h.frame == k) return &h;
    if (!window_ && h.start >= 0 && h.frame == k - 1) {
        FootFree q;
        if (!free && !foot_free(agent, k, foot, q)) return nullptr;
        follow(h, agent, k, foot, free ? *free : q, plant, false);
        h.frame = k;
        return &h;
    }
    return follow_contact(agent, k, foot, free, segments_, h) ? &h : nullptr;
}

void CrowdPoser::contact_runs(int agent, std::int64_t k, int foot, std::vector<Segment>& runs) {
    // From frame k back to the contact's start (latest first), across clips.
    const MotionGraph& g = sources_->graph();
    runs.clear();
    for (std::int64_t cur = k; cur >= 0;) {
        AgentClipAt at;
        if (!agent_clip_at(record_, g, agent, cur, at)) break;
        const GraphClip& gc = g.clips[std::size_t(at.placed->clip)];
        const FootTrack& t = sources_->get(gc.source).feet[std::size_t(foot)];
        const Plant p = plant_in(at, cur, foot, lock_.carry);
        if (p == Plant::Free) break;
        // A run of the clip's own contact, or frames carried from the clip before (from the clip's start).
        const std::int64_t begin = t.plant[std::size_t(at.sample)] == Plant::Free
                                       ? at.placed->start
                                       : cur - (at.sample - std::max(t.run_begin[std::size_t(at.sample)], gc.first));
        if (!runs.empty() && runs.back().plant == p)
            runs.back().begin = begin;
        else
            runs.push_back({begin, p});
        cur = begin - 1;
    }
}

bool CrowdPoser::follow_contact(int agent, std::int64_t k, int foot, const FootFree* free, std::vector<Segment>& runs,
                                Hold& h) {
    contact_runs(agent, k, foot, runs);
    if (runs.empty()) return false;
    // Followed frame by frame from the start, or on from where h was left.
    const std::int64_t start = runs.back().begin;
    // A window of samples (use_samples) may have moved since: its disks bound the hold, so start over. Where
    // the foot comes down is read first: h may still be the hold let go just before.
    if (window_ || h.start != start || h.frame > k || h.frame < start) {
        glm::dvec3 from{0.0};
        held_before(agent, start, foot, from);
        h = {start, start - 1};
        h.from = from;
    }
    std::size_t seg = runs.size() - 1;
    for (std::int64_t m = h.frame + 1; m <= k; ++m) {
        while (seg > 0 && runs[seg - 1].begin <= m) --seg;
        FootFree q;
        if (m == k && free)
            q = *free;
        else if (!foot_free(agent, m, foot, q))
            return false;
        follow(h, agent, m, foot, q, runs[seg].plant, m == start);
        h.frame = m;
    }
    return true;
}

bool CrowdPoser::hold_at(int agent, std::int64_t k, int foot, Hold& out) {
    // The kept hold where it stands at frame k, else one followed apart: this may run inside contact_target,
    // whose hold and runs it must leave alone.
    if (!window_ && !holds_.empty()) {
        const Hold& kept = holds_[std::size_t(agent)][std::size_t(foot)];
        if (kept.start >= 0 && kept.frame == k) {
            out = kept;
            return true;
        }
    }
    std::vector<Segment> runs;
    out = {};
    return follow_contact(agent, k, foot, nullptr, runs, out);
}

void CrowdPoser::follow(Hold& h, int agent, std::int64_t k, int foot, const FootFree& q, Plant plant, bool first) {
    // A hold's first frame has nothing to glide from: no lookup of the clip's own point.
    AgentClipAt at;
    glm::dvec3 own;
    const bool glides = !first && played_at(agent, k, at) && own_point(at, foot, plant, own);
    hold_step(h, q, plant, first, glides ? &own : nullptr, h.from);
}

bool CrowdPoser::played_at(int agent, std::int64_t k, AgentClipAt& at) const {
    if (agent == posed_agent_ && k <= posed_frame_ && k >= posed_.placed->start) {
        at = posed_;  // in the clip of the frame being posed: no search
        at.sample -= int(posed_frame_ - k);
        return true;
    }
    if (agent == posed_agent_ && posed_.index > 0 && k < posed_.placed->start && k >= (posed_.placed - 1)->start) {
        // In the clip before it (a blend's and a release's lookups back): no search either.
        const PlacedClip* before = posed_.placed - 1;
        const GraphClip& gc = sources_->graph().clips[std::size_t(before->clip)];
        if (k - before->start >= std::int64_t(gc.exit - gc.first)) return false;
        at = {before, posed_.index - 1, gc.first + int(k - before->start)};
        return true;
    }
    return k >= 0 && agent_clip_at(record_, sources_->graph(), agent, k, at);
}

bool CrowdPoser::own_point(const AgentClipAt& at, int foot, Plant plant, glm::dvec3& out) {
    // Where the clip played has the planted point itself; none for a contact carried over.
    if (!(lock_.glide > 0 || lock_.glide_height > 0)) return false;
    const GraphClip& gc = sources_->graph().clips[std::size_t(at.placed->clip)];
    const PoseSource& src = sources_->get(gc.source);
    const FootTrack& t = src.feet[std::size_t(foot)];
    const std::size_t i = std::size_t(at.sample);
    if (i >= t.plant.size() || t.plant[i] != plant) return false;
    if (own_.placed != at.placed) own_ = {at.placed, Rigid2::of(source_to_world(src, gc, at.placed->place))};
    const glm::dvec3& p = plant == Plant::Toe ? t.toe[i] : t.heel[i];
    out = {own_.to_world.apply_x(p.x, p.y), own_.to_world.apply_y(p.x, p.y), p.z};
    return true;
}

bool CrowdPoser::ankle_target(int agent, std::int64_t k, int foot, const FootFree& free, AnkleTarget& out) {
    // A contact first, then a pin (stepped at every frame, so that it follows on), then a release.
    const Plant plant = plant_at(agent, k, foot, lock_.carry);
    const Hold* h = plant != Plant::Free ? contact_target(agent, k, foot, plant, &free) : nullptr;
    if (plant != Plant::Free && !h) return false;
    const Pin* pin = lock_.pin ? pin_target(agent, k, foot, free, plant) : nullptr;
    if (h) {
        out = {h->target, h->dragged, false};
        return true;
    }
    if (pin) {
        out = {free.ankle + pin->shift, pin->pinned ? pin->dragged : 0.0, pin->pinned};
        return true;
    }
    out = {};
    return released(agent, k, foot, free, out.at);
}

bool CrowdPoser::released(int agent, std::int64_t k, int foot, const FootFree& free, glm::dvec3& target) {
    // Let go over the release from where the contact's last frame held it.
    const int release = release_frames();
    if (free_for(agent, k, foot, release)) return false;
    for (int d = 1; d <= release; ++d) {
        const Plant then = plant_at(agent, k - d, foot, lock_.carry);
        if (then == Plant::Free) continue;
        const Hold* h = contact_target(agent, k - d, foot, then, nullptr);
        if (!h) return false;
        target = within_reach(free.ankle + release_shift(h->toe, h->target - h->ankle, d, release, free), free);
        return true;
    }
    return false;
}

// d frames into the release: smoothstep from the hold to the free pose. In the world (release_in_world), the
// toe goes from where it was held to the free pose's; else the hold's last correction decays against the
// free pose. Heights decay against the pose either way.
glm::dvec3 CrowdPoser::release_shift(const glm::dvec3& toe, const glm::dvec3& correction, int d, int release,
                                     const FootFree& free) const {
    const double s = double(d) / double(release + 1), w = 1.0 - s * s * (3.0 - 2.0 * s);
    if (!lock_.release_in_world) return w * correction;
    return w * glm::dvec3(toe.x - free.toe.x, toe.y - free.toe.y, correction.z);
}

void CrowdPoser::start_pin(Pin& p, int agent, const PlacedClip* placed, int foot) {
    // Before the clip's first frame: the last contact frame within a release of it.
    p = {placed, placed->start - 1};
    const int release = release_frames();
    for (int d = 1; d <= release + 1 && p.contact < 0; ++d)
        if (plant_at(agent, placed->start - d, foot, lock_.carry) != Plant::Free) p.contact = placed->start - d;
}

bool CrowdPoser::pin_at(Pin& p, int agent, std::int64_t k, int foot, const FootFree* free, const Plant* plant) {
    // Only in the blend after a clip start and the release after it; followed on from frame k - 1, or from the
    // clip's start over again.
    AgentClipAt at;
    const int release = release_frames();
    if (!played_at(agent, k, at) || !in_blend(k - at.placed->start - release - 1) || !blends_into(at)) return false;
    if (window_ || p.placed != at.placed || p.frame != k - 1 || p.frame < at.placed->start - 1)
        start_pin(p, agent, at.placed, foot);
    for (std::int64_t m = p.frame + 1; m <= k; ++m) {
        FootFree q;
        if (m == k && free)
            q = *free;
        else if (!foot_free(agent, m, foot, q))
            return false;
        pin_step(p, agent, m, foot, q, m == k && plant ? *plant : plant_at(agent, m, foot, lock_.carry));
    }
    return p.holds;
}

void CrowdPoser::pin_step(Pin& p, int agent, std::int64_t m, int foot, const FootFree& q, Plant plant) {
    // Let go as after a contact once no longer pinned.
    p.frame = m;
    if (plant != Plant::Free) p.contact = m;
    if (pins(p, agent, m, foot, q, plant)) {
        p.correction = {p.toe.x - q.toe.x, p.toe.y - q.toe.y, p.height};
        const glm::dvec3 held = within_reach(q.ankle + p.correction, q);
        p.dragged = glm::length(held - (q.ankle + p.correction));
        p.shift = held - q.ankle;
        p.holds = true;
        return;
    }
    if (p.pinned) p.freed = m;
    p.pinned = false;
    const int release = release_frames();
    p.holds = p.freed >= 0 && m - p.freed < release;
    if (p.holds)
        p.shift =
            within_reach(q.ankle + release_shift(p.toe, p.correction, int(m - p.freed) + 1, release, q), q) - q.ankle;
}

bool CrowdPoser::pins(Pin& p, int agent, std::int64_t m, int foot, const FootFree& q, Plant plant) {
    // In the blend with the toe down, no contact, and, in a walk, the clip itself moving the toe slower than
    // pin_speed (else it is a swing as captured): a contact that ended at m - 1 goes on pinned where it held
    // the toe; else the toe is pinned where it came down, once per blend and not while a contact is let go (a
    // pin let go and pinned again would start over where the free pose has it).
    if (!in_blend(m - p.placed->start) || !(q.toe.z < lock_.toe_down) || plant != Plant::Free) return false;
    const bool shuffles = lock_.pin_shuffles && kinds_[std::size_t(p.placed->clip)] != ClipKind::Walk;
    if (!shuffles && own_toe_speed(p.placed, m - p.placed->start, foot) > lock_.pin_speed) return false;
    if (p.pinned) return true;
    const int release = release_frames();
    if (p.contact >= 0 && p.contact == m - 1) {
        Hold h;
        if (!hold_at(agent, m - 1, foot, h)) return false;
        p.toe = h.toe;
        p.height = h.target.z - h.ankle.z;
    } else if (p.freed >= 0 || (p.contact >= 0 && m - p.contact <= release)) {
        return false;
    } else {
        p.toe = q.toe;
        p.height = 0;
    }
    p.pinned = true;
    p.freed = -1;
    return true;
}

double CrowdPoser::own_toe_speed(const PlacedClip* placed, std::int64_t i, int foot) const {
    // From the source's toe track (ground speed does not change with the placement).
    const GraphClip& gc = sources_->graph().clips[std::size_t(placed->clip)];
    const FootTrack& t = sources_->get(gc.source).feet[std::size_t(foot)];
    const std::size_t s = std::size_t(gc.first + i);
    if (s < 1 || s >= t.toe.size()) return 0;
    return std::hypot(t.toe[s].x - t.toe[s - 1].x, t.toe[s].y - t.toe[s - 1].y) / record_.dt;
}

bool CrowdPoser::held_before(int agent, std::int64_t start, int foot, glm::dvec3& out) {
    // A pin, or the release of a contact that ended up to `release` frames before.
    if (lock_.pin && pin_offset(agent, start - 1, foot, out)) return true;
    const int release = release_frames();
    for (int d = 1; d <= release; ++d) {
        if (plant_at(agent, start - 1 - d, foot, lock_.carry) == Plant::Free) continue;
        Hold h;
        FootFree q;
        if (!hold_at(agent, start - 1 - d, foot, h) || !foot_free(agent, start - 1, foot, q)) return false;
        const glm::dvec3 target = within_reach(q.ankle + release_shift(h.toe, h.target - h.ankle, d, release, q), q);
        out = {target.x - q.ankle.x, target.y - q.ankle.y, 0.0};
        return true;
    }
    return false;
}

bool CrowdPoser::pin_offset(int agent, std::int64_t k, int foot, glm::dvec3& out) {
    // The kept pin where it stands at frame k, else one followed apart (this runs inside contact_target and
    // pin_at, whose state it must leave alone).
    const Pin* kept = pins_.empty() ? nullptr : &pins_[std::size_t(agent)][std::size_t(foot)];
    Pin apart;
    if (window_ || !kept || kept->frame != k || !kept->placed || k < kept->placed->start) {
        if (!pin_at(apart, agent, k, foot, nullptr, nullptr)) return false;
        kept = &apart;
    }
    if (!kept->holds) return false;
    out = {kept->shift.x, kept->shift.y, 0.0};
    return true;
}

const CrowdPoser::Pin* CrowdPoser::pin_target(int agent, std::int64_t k, int foot, const FootFree& free, Plant plant) {
    // Most frames are outside every blend: answered from the clip posed.
    if (agent == posed_agent_ && k == posed_frame_ &&
        (posed_.index == 0 || k - posed_.placed->start > blend_frames_ + release_frames()))
        return nullptr;
    if (pins_.empty()) pins_.resize(record_.tracks.size());
    Pin& p = pins_[std::size_t(agent)][std::size_t(foot)];
    return pin_at(p, agent, k, foot, &free, &plant) ? &p : nullptr;
}

void CrowdPoser::lock_feet(int agent, std::int64_t k, std::vector<glm::dvec3>& out, FeetAt* feet) {
    std::array<AnkleTarget, 2> targets{};
    std::array<bool, 2> held{}, bent{};
    const Envelope disk = blend_.window > 0 ? disk_ : envelope(agent, k);  // before foot_free moves disk_
    for (int f = 0; f < 2; ++f) {
        const RigLeg& leg = legs_[std::size_t(f)];
        if (!leg.complete()) continue;
        const FootFree free{out[std::size_t(leg.hip)],
                            out[std::size_t(leg.knee)],
                            out[std::size_t(leg.ankle)],
                            out[std::size_t(leg.toe)],
                            out[0],
                            disk};
        held[std::size_t(f)] = ankle_target(agent, k, f, free, targets[std::size_t(f)]);
        // A target on the free ankle (over a third of held frames: a hold's first frame, a pin's) leaves the
        // leg as it is: no IK.
        if (!held[std::size_t(f)] || targets[std::size_t(f)].at == free.ankle) continue;
        bent[std::size_t(f)] = true;
        const LegSolve s = two_joint_ik(out[std::size_t(leg.hip)], out[std::size_t(leg.knee)], free.ankle,
                                        targets[std::size_t(f)].at, free.toe - free.ankle);
        bend_leg(leg, s, out);
    }
    // The bent legs inside the disk. Blended, free_pose held every joint inside this same disk, so a leg
    // that was not bent is inside already; unblended it was not, and both legs are held in.
    for (std::size_t f = 0; f < 2; ++f)
        if (bent[f] || (!(blend_.window > 0) && (held[0] || held[1]))) hold_inside(leg_joints_[f], disk, out);
    if (!feet) return;
    for (std::size_t f = 0; f < 2; ++f) {
        feet->held[f] = held[f];
        feet->pinned[f] = held[f] && targets[f].pinned;
        feet->dragged[f] = targets[f].dragged;
        if (held[f]) feet->residual[f] = glm::length(out[std::size_t(legs_[f].ankle)] - targets[f].at);
    }
}

}  // namespace mobb::crowd
