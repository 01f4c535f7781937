// Foot locking in CrowdPoser (agent_pose.h): a planted foot held where its contact began, the leg bent to
// reach it (two_joint_ik), the hold let go over FootLock::release after the contact.
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

bool CrowdPoser::in_blend(std::int64_t i) const { return blend_.window > 0 && double(i) < blend_.window / record_.dt; }

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
    const int up = int(std::ceil(blend_.window / record_.dt)) + int(std::lround(lock_.release / record_.dt));
    if (!up_from(sources_->get(gc.source).feet[std::size_t(foot)], gc.first, up)) return c.plant;
    const PlacedClip& prev = at.placed[-1];  // the agent's clips are one vector: the clip before
    const GraphClip& gp = g.clips[std::size_t(prev.clip)];
    if (prev.start + (gp.exit - gp.first) != at.placed->start) return c.plant;  // not back to back: no blend
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
    const double dx = own.x - point.x, dy = own.y - point.y, d = std::hypot(dx, dy);
    const double most = lock_.glide * record_.dt, f = d > most ? most / d : 1.0;
    const double rise = lock_.glide_height * record_.dt;
    point += glm::dvec3(dx * f, dy * f, std::clamp(own.z - point.z, -rise, rise));
}

void CrowdPoser::hold_step(Hold& h, const FootFree& q, Plant plant, bool first, const glm::dvec3* own) const {
    // The first planted point stays where it came down; a next one where the hold puts it then. Either
    // glides towards the clip's own (FootLock::glide).
    if (first)
        h.point = planted_point(q.ankle, q.toe, plant);
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
}

glm::dvec3 CrowdPoser::within_reach(const glm::dvec3& target, const FootFree& q) const {
    // The leg stretched at most to lock_.reach of its length (or the free pose's own stretch): the target
    // raised to where the leg reaches it (FootLock::lift), else towards the hip; then on the ground inside
    // the disk the collision answers used, towards the root.
    const double leg = glm::length(q.knee - q.hip) + glm::length(q.ankle - q.knee);
    const double limit = std::min(leg, std::max(glm::length(q.ankle - q.hip), lock_.reach * leg));
    glm::dvec3 out = target;
    const double ground = std::hypot(target.x - q.hip.x, target.y - q.hip.y);
    if (lock_.lift && ground < limit) out.z = std::max(out.z, q.hip.z - std::sqrt(limit * limit - ground * ground));
    const double d = glm::length(out - q.hip);
    if (d > limit) out = q.hip + (out - q.hip) * (limit / d);
    const double dx = out.x - q.root.x, dy = out.y - q.root.y, from_root = std::hypot(dx, dy);
    if (from_root > q.disk) {
        const double f = q.disk * (1 - 1e-12) / from_root;
        out = {q.root.x + dx * f, q.root.y + dy * f, out.z};
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
    // The contact's runs of equal plant, from frame k back to its start (latest first), across clips.
    const MotionGraph& g = sources_->graph();
    segments_.clear();
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
        if (!segments_.empty() && segments_.back().plant == p)
            segments_.back().begin = begin;
        else
            segments_.push_back({begin, p});
        cur = begin - 1;
    }
    if (segments_.empty()) return nullptr;
    // Followed frame by frame from the start, or on from where this agent's hold was left.
    const std::int64_t start = segments_.back().begin;
    // A window of samples (use_samples) may have moved since: its disks bound the hold, so start over.
    if (window_ || h.start != start || h.frame > k || h.frame < start) h = {start, start - 1};
    std::size_t seg = segments_.size() - 1;
    for (std::int64_t m = h.frame + 1; m <= k; ++m) {
        while (seg > 0 && segments_[seg - 1].begin <= m) --seg;
        FootFree q;
        if (m == k && free)
            q = *free;
        else if (!foot_free(agent, m, foot, q))
            return nullptr;
        follow(h, agent, m, foot, q, segments_[seg].plant, m == start);
        h.frame = m;
    }
    return &h;
}

void CrowdPoser::follow(Hold& h, int agent, std::int64_t k, int foot, const FootFree& q, Plant plant, bool first) {
    // A hold's first frame has nothing to glide from: no lookup of the clip's own point.
    AgentClipAt at;
    glm::dvec3 own;
    const bool glides = !first && played_at(agent, k, at) && own_point(at, foot, plant, own);
    hold_step(h, q, plant, first, glides ? &own : nullptr);
}

bool CrowdPoser::played_at(int agent, std::int64_t k, AgentClipAt& at) const {
    if (agent == posed_agent_ && k <= posed_frame_ && k >= posed_.placed->start) {
        at = posed_;  // in the clip of the frame being posed: no search
        at.sample -= int(posed_frame_ - k);
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

bool CrowdPoser::ankle_target(int agent, std::int64_t k, int foot, const FootFree& free, glm::dvec3& target,
                              double& dragged) {
    if (const Plant plant = plant_at(agent, k, foot, lock_.carry); plant != Plant::Free) {
        const Hold* h = contact_target(agent, k, foot, plant, &free);
        if (!h) return false;
        target = h->target;
        dragged = h->dragged;
        return true;
    }
    // Released: the correction at the contact's last frame, decaying (smoothstep) over the release.
    const int release = int(std::lround(lock_.release / record_.dt));
    if (free_for(agent, k, foot, release)) return false;
    for (int d = 1; d <= release; ++d) {
        const Plant then = plant_at(agent, k - d, foot, lock_.carry);
        if (then == Plant::Free) continue;
        const Hold* h = contact_target(agent, k - d, foot, then, nullptr);
        if (!h) return false;
        target = within_reach(free.ankle + release_shift(h->target - h->ankle, d, release, free), free);
        return true;
    }
    return false;
}

// The correction d frames after a contact's last frame: smoothstep down to 0 over the release. While the
// toe is still on the ground (FootLock::release_height) its horizontal part stays as long as what is left can
// be gone by the release's end at FootLock::release_speed, and leaves at that speed after.
glm::dvec3 CrowdPoser::release_shift(const glm::dvec3& correction, int d, int release, const FootFree& free) const {
    const double s = double(d) / double(release + 1), w = 1.0 - s * s * (3.0 - 2.0 * s);
    glm::dvec3 out = w * correction;
    const double ground = std::hypot(correction.x, correction.y);
    if (free.toe.z >= lock_.release_height || !(ground > 0)) return out;
    const double in_time = double(release + 1 - d) * lock_.release_speed * record_.dt / ground;
    const double kept = std::max(w, std::min(1.0, in_time));
    out.x = kept * correction.x;
    out.y = kept * correction.y;
    return out;
}

void CrowdPoser::lock_feet(int agent, std::int64_t k, std::vector<glm::dvec3>& out, FeetAt* feet) {
    std::array<glm::dvec3, 2> targets{};
    std::array<bool, 2> held{};
    std::array<double, 2> dragged{};
    const double disk = blend_.window > 0 ? disk_ : envelope(agent, k);  // before foot_free moves disk_
    for (int f = 0; f < 2; ++f) {
        const RigLeg& leg = legs_[std::size_t(f)];
        if (!leg.complete()) continue;
        const FootFree free{out[std::size_t(leg.hip)],
                            out[std::size_t(leg.knee)],
                            out[std::size_t(leg.ankle)],
                            out[std::size_t(leg.toe)],
                            out[0],
                            disk};
        held[std::size_t(f)] = ankle_target(agent, k, f, free, targets[std::size_t(f)], dragged[std::size_t(f)]);
        if (!held[std::size_t(f)]) continue;
        const LegSolve s = two_joint_ik(out[std::size_t(leg.hip)], out[std::size_t(leg.knee)], free.ankle,
                                        targets[std::size_t(f)], free.toe - free.ankle);
        bend_leg(leg, s, out);
    }
    // The bent legs inside the disk. Blended, free_pose held every joint inside this same disk, so a leg
    // that was not bent is inside already; unblended it was not, and both legs are held in.
    for (std::size_t f = 0; f < 2; ++f)
        if (held[f] || (!(blend_.window > 0) && (held[0] || held[1]))) hold_inside(leg_joints_[f], disk, out);
    if (!feet) return;
    for (std::size_t f = 0; f < 2; ++f) {
        feet->held[f] = held[f];
        feet->dragged[f] = dragged[f];
        if (held[f]) feet->residual[f] = glm::length(out[std::size_t(legs_[f].ankle)] - targets[f]);
    }
}

}  // namespace mobb::crowd
