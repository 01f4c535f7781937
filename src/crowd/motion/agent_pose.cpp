#include "mobb/crowd/motion/agent_pose.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "mobb/crowd/graph/pose_distance.h"

namespace mobb::crowd {

namespace {

bool ends_with(const std::string& name, const std::string& suffix) {
    return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The first joint whose name ends with `suffix`, -1 when none.
int joint_named(const std::vector<std::string>& names, const std::string& suffix) {
    for (std::size_t j = 0; j < names.size(); ++j)
        if (ends_with(names[j], suffix)) return int(j);
    return -1;
}

// The take's foot contacts from its heels (ankles) and toes, heights above its lowest joint.
std::array<FootTrack, 2> source_contacts(const io::Clip& clip, double floor) {
    const io::Skeleton& sk = clip.animation.skeleton;
    std::array<std::vector<glm::dvec3>, 2> heel, toe;
    for (std::size_t f = 0; f < 2; ++f) {
        const std::string side = f ? "R_" : "L_";
        const int h = joint_named(sk.names, side + "Foot"), t = joint_named(sk.names, side + "ToeBase");
        if (h < 0 || t < 0) return {};
        for (int i = 0; i < clip.animation.frames(); ++i) {
            const glm::dvec3 ph = io::to_ground(clip.animation.at(i, h), clip.up);
            const glm::dvec3 pt = io::to_ground(clip.animation.at(i, t), clip.up);
            heel[f].push_back({ph.x, ph.y, ph.z - floor});
            toe[f].push_back({pt.x, pt.y, pt.z - floor});
        }
    }
    return detect_contacts(heel, toe, clip.animation.dt);
}

std::unique_ptr<PoseSource> make_source(const MotionGraph& g, int source) {
    auto out = std::make_unique<PoseSource>();
    try {
        auto clip = std::make_shared<io::Clip>(load_graph_source(g, source));
        const PoseTrack track = pose_track(*clip, select_joints(clip->animation.skeleton));
        for (int f = 0; f < track.frames; ++f) {
            out->root_x.push_back(track.root[std::size_t(f)].x);
            out->root_y.push_back(track.root[std::size_t(f)].y);
            out->heading.push_back(track.heading[std::size_t(f)]);
        }
        double lowest = 1e300;
        for (const glm::dvec3& p : clip->animation.positions) lowest = std::min(lowest, io::to_ground(p, clip->up).z);
        out->floor = clip->animation.positions.empty() ? 0.0 : lowest;
        out->feet = source_contacts(*clip, out->floor);
        out->clip = std::move(clip);
    } catch (const std::exception& e) {
        out->error = e.what();
    }
    return out;
}

const PoseSource& loaded(PoseSources& sources, int source) {
    const PoseSource& s = sources.get(source);
    if (!s.clip) throw io::LoadError(s.error);
    return s;
}

/// The last frame agent `agent` has a clip for (its clips end, or it left), -1 when none.
std::int64_t last_frame(const Record& r, const MotionGraph& g, int agent) {
    const AgentTrack& t = r.tracks[std::size_t(agent)];
    if (t.clips.empty()) return -1;
    const PlacedClip& p = t.clips.back();
    if (p.clip < 0 || std::size_t(p.clip) >= g.clips.size()) return -1;
    const GraphClip& gc = g.clips[std::size_t(p.clip)];
    std::int64_t last = std::min<std::int64_t>(p.start + (gc.exit - gc.first), r.frames) - 1;
    if (t.left_frame) last = std::min(last, *t.left_frame - 1);
    return last;
}

}  // namespace

std::string record_graph_file(const Record& r) {
    if (!std::filesystem::exists(r.graph) &&
        std::filesystem::path(r.graph).lexically_normal() == "assets/graphs/cmu_locomotion.json")
        return default_graph_file();
    return r.graph;
}

Placement source_to_world(const PoseSource& s, const GraphClip& clip, const Placement& place) {
    const std::size_t i = std::size_t(clip.first);
    if (i >= s.heading.size()) return place;
    // world = R(theta) R(-h) (p - o) + (x, y) = R(theta - h) p + (x, y) - R(theta - h) o.
    const double a = place.theta - s.heading[i];
    const double c = std::cos(a), sn = std::sin(a);
    const double ox = s.root_x[i], oy = s.root_y[i];
    return {place.x - (c * ox - sn * oy), place.y - (sn * ox + c * oy), a, place.t0};
}

bool agent_clip_at(const Record& r, const MotionGraph& g, int agent, std::int64_t k, AgentClipAt& out) {
    if (agent < 0 || std::size_t(agent) >= r.tracks.size() || k < 0 || k >= r.frames) return false;
    const auto& clips = r.tracks[std::size_t(agent)].clips;
    // The last clip started at or before frame k (clips are in time order).
    auto it = std::upper_bound(clips.begin(), clips.end(), k,
                               [](std::int64_t f, const PlacedClip& p) { return f < p.start; });
    if (it == clips.begin()) return false;
    const PlacedClip& p = *std::prev(it);
    if (p.clip < 0 || std::size_t(p.clip) >= g.clips.size()) return false;
    const GraphClip& gc = g.clips[std::size_t(p.clip)];
    const std::int64_t i = k - p.start;
    if (i >= std::int64_t(gc.exit - gc.first)) return false;
    out.placed = &p;
    out.index = int(std::prev(it) - clips.begin());
    out.sample = gc.first + int(i);
    return true;
}

const PoseSource& PoseSources::load(int source) {
    if (sources_.empty()) sources_.resize(graph_->sources.size());
    auto& slot = sources_.at(std::size_t(source));
    if (!slot) {
        slot = make_source(*graph_, source);
        if (!slot->error.empty() && error_.empty()) error_ = slot->error;
        contacts_.resize(graph_->clips.size());
        for (std::size_t c = 0; c < graph_->clips.size(); ++c)
            if (graph_->clips[c].source == source) contacts_[c] = clip_contacts(slot->feet, graph_->clips[c]);
    }
    return *slot;
}

const std::vector<ContactSpan>& PoseSources::contacts(int clip) {
    get(graph_->clips.at(std::size_t(clip)).source);
    return contacts_[std::size_t(clip)];
}

int PoseSources::loaded() const {
    return int(std::count_if(sources_.begin(), sources_.end(), [](const auto& s) { return s && s->clip; }));
}

Rig crowd_rig(PoseSources& sources, RigJoints joints) {
    const MotionGraph& g = sources.graph();
    if (g.sources.empty()) throw GraphError("graph: no sources");
    std::vector<std::map<std::string, int>> by_name(g.sources.size());
    for (std::size_t s = 0; s < g.sources.size(); ++s) {
        const io::Skeleton& sk = loaded(sources, int(s)).clip->animation.skeleton;
        for (int j = sk.size() - 1; j >= 0; --j) by_name[s][sk.names[std::size_t(j)]] = j;  // first of a name wins
    }
    const io::Skeleton& first = sources.get(0).clip->animation.skeleton;
    std::vector<bool> keep(std::size_t(first.size()), false);
    if (joints == RigJoints::Major) {
        for (const std::string& n : select_joints(first).names) keep[std::size_t(by_name[0][n])] = true;
    } else {
        for (int j = 0; j < first.size(); ++j) keep[std::size_t(j)] = by_name[0][first.names[std::size_t(j)]] == j;
    }
    for (int j = 0; j < first.size(); ++j)
        for (const auto& names : by_name)
            if (!names.count(first.names[std::size_t(j)])) keep[std::size_t(j)] = false;
    const int root = first.root;  // joint 0 is each source's own root, whatever its name: its path's root
    Rig rig;
    std::vector<int> index(std::size_t(first.size()), -1);
    auto add = [&](int j) {
        index[std::size_t(j)] = rig.size();
        int p = first.parents[std::size_t(j)];
        while (p >= 0 && index[std::size_t(p)] < 0) p = first.parents[std::size_t(p)];
        rig.names.push_back(first.names[std::size_t(j)]);
        rig.parents.push_back(j == root ? -1 : (p >= 0 ? index[std::size_t(p)] : 0));
    };
    add(root);
    for (int j = 0; j < first.size(); ++j)
        if (keep[std::size_t(j)] && j != root) add(j);
    rig.source_joints.resize(g.sources.size());
    for (std::size_t s = 0; s < g.sources.size(); ++s) {
        const io::Skeleton& sk = sources.get(int(s)).clip->animation.skeleton;
        rig.source_joints[s].push_back(sk.root);
        for (std::size_t j = 1; j < rig.names.size(); ++j) rig.source_joints[s].push_back(by_name[s].at(rig.names[j]));
    }
    return rig;
}

std::array<RigLeg, 2> rig_legs(const Rig& rig) {
    std::array<RigLeg, 2> legs;
    for (std::size_t f = 0; f < 2; ++f) {
        RigLeg& leg = legs[f];
        const std::string side = f ? "R_" : "L_";
        leg.hip = joint_named(rig.names, side + "Thigh");
        leg.knee = joint_named(rig.names, side + "Calf");
        leg.ankle = joint_named(rig.names, side + "Foot");
        leg.toe = joint_named(rig.names, side + "ToeBase");
        if (!leg.complete()) continue;
        // A joint hangs from the nearest of ankle, knee and hip above it (parents come before children).
        std::vector<int> segment(std::size_t(rig.size()), 0);
        for (int j = 1; j < rig.size(); ++j) {
            const int p = rig.parents[std::size_t(j)];
            segment[std::size_t(j)] = p == leg.ankle  ? 3
                                      : p == leg.knee ? 2
                                      : p == leg.hip  ? 1
                                                      : segment[std::size_t(p)];
            if (j == leg.knee || j == leg.ankle) continue;
            if (segment[std::size_t(j)] > 0) leg.hanging.push_back({j, segment[std::size_t(j)]});
        }
    }
    return legs;
}

CrowdPoser::CrowdPoser(const Record& record, std::shared_ptr<PoseSources> sources, RigJoints joints, PoseBlend blend,
                       FootLock lock)
    : record_(record),
      sources_(std::move(sources)),
      blend_(blend),
      lock_(lock),
      release_frames_(int(std::lround(lock.release / record.dt))),
      blend_frames_(blend.window > 0 ? std::int64_t(std::ceil(blend.window / record.dt)) : 0) {
    const MotionGraph& g = sources_->graph();
    if (std::abs(record.dt - g.dt()) > 1e-9)
        throw GraphError("record dt " + std::to_string(record.dt) + " s differs from its graph's " +
                         std::to_string(g.dt()) + " s");
    check_graph_clips(record, g.clips.size());
    rig_ = crowd_rig(*sources_, joints);
    legs_ = rig_legs(rig_);
    for (int j = 0; j < rig_.size(); ++j) all_.push_back(j);
    kinds_ = kinds_of(g);
    for (std::size_t f = 0; f < 2; ++f) {
        const RigLeg& leg = legs_[f];
        if (!leg.complete()) continue;
        foot_[f] = {0, leg.hip, leg.knee, leg.ankle, leg.toe};
        leg_joints_[f] = {0, leg.knee, leg.ankle};
        for (const auto& h : leg.hanging) leg_joints_[f].push_back(h.first);
    }
}

bool CrowdPoser::raw(const AgentClipAt& at, int sample, const std::vector<int>& joints, std::vector<glm::dvec3>& out) {
    const GraphClip& gc = sources_->graph().clips[std::size_t(at.placed->clip)];
    const PoseSource& src = loaded(*sources_, gc.source);
    if (sample < 0 || sample >= src.clip->animation.frames()) return false;
    const Rigid2 m = Rigid2::of(source_to_world(src, gc, at.placed->place));
    const std::vector<int>& source_joints = rig_.source_joints[std::size_t(gc.source)];
    out.resize(source_joints.size());
    for (int j : joints) {
        const glm::dvec3 p = io::to_ground(src.clip->animation.at(sample, source_joints[std::size_t(j)]), src.clip->up);
        out[std::size_t(j)] = {m.apply_x(p.x, p.y), m.apply_y(p.x, p.y), p.z - src.floor};
    }
    out[0].z = 0.0;  // the path's point: sources root their skeletons at the hips or at the floor
    return true;
}

bool CrowdPoser::pose(int agent, std::int64_t k, std::vector<glm::dvec3>& out) { return pose(agent, k, out, c_); }

bool CrowdPoser::pose(int agent, std::int64_t k, std::vector<glm::dvec3>& out, std::vector<glm::dvec3>& raw_out) {
    return pose(agent, k, out, raw_out, u_, nullptr);
}

bool CrowdPoser::pose(int agent, std::int64_t k, std::vector<glm::dvec3>& out, std::vector<glm::dvec3>& raw_out,
                      std::vector<glm::dvec3>& unlocked, FeetAt* feet) {
    if (agent < 0 || std::size_t(agent) >= record_.tracks.size() || k < 0 || k >= record_.frames) return false;
    const std::int64_t last = last_frame(record_, sources_->graph(), agent);
    if (last < 0) return false;
    k = std::min(k, last);
    if (!free_pose(agent, k, all_, out, raw_out)) return false;
    unlocked = out;
    posed_agent_ = agent_clip_at(record_, sources_->graph(), agent, k, posed_) ? agent : -1;
    posed_frame_ = k;
    if (feet) {
        *feet = {};
        for (int f = 0; f < 2; ++f)
            if (legs_[std::size_t(f)].complete()) {
                feet->plant[std::size_t(f)] = plant_at(agent, k, f, false);
                feet->hold[std::size_t(f)] =
                    lock_.on ? plant_at(agent, k, f, lock_.carry) : feet->plant[std::size_t(f)];
            }
    }
    if (lock_.on) lock_feet(agent, k, out, feet);
    return true;
}

bool CrowdPoser::blends_into(const AgentClipAt& at) const {
    // Only clips played back to back blend (the previous one ran to its exit).
    if (at.index == 0) return false;
    const PlacedClip& prev = at.placed[-1];  // the agent's clips are one vector: the clip before
    const GraphClip& gp = sources_->graph().clips[std::size_t(prev.clip)];
    return prev.start + (gp.exit - gp.first) == at.placed->start;
}

bool CrowdPoser::free_pose(int agent, std::int64_t k, const std::vector<int>& joints, std::vector<glm::dvec3>& out,
                           std::vector<glm::dvec3>& raw_out) {
    const MotionGraph& g = sources_->graph();
    AgentClipAt at;
    if (!agent_clip_at(record_, g, agent, k, at) || !raw(at, at.sample, joints, raw_out)) return false;
    out.resize(raw_out.size());
    for (int j : joints) out[std::size_t(j)] = raw_out[std::size_t(j)];
    if (!(blend_.window > 0)) return true;
    const AgentTrack& track = record_.tracks[std::size_t(agent)];
    const double window = blend_.window / record_.dt;  // frames
    const double i = double(k - at.placed->start);
    if (at.index > 0 && i < window) {
        const PlacedClip& prev = track.clips[std::size_t(at.index - 1)];
        const GraphClip& gp = g.clips[std::size_t(prev.clip)];
        const GraphClip& gc = g.clips[std::size_t(at.placed->clip)];
        const AgentClipAt from{&prev, at.index - 1, gp.exit};
        if (blends_into(at) && raw(from, gp.exit, joints, a_) && raw(at, gc.first, joints, b_)) {
            const double s = i / window, w = 1.0 - s * s * (3.0 - 2.0 * s);
            // Offsets in the ground relative to the root, heights as they are (the root is on the floor).
            for (int j : joints)
                if (j > 0) out[std::size_t(j)] += w * ((a_[std::size_t(j)] - a_[0]) - (b_[std::size_t(j)] - b_[0]));
        }
    }
    disk_ = envelope(agent, k);
    hold_inside(joints, disk_, out);
    return true;
}

CrowdPoser::Envelope CrowdPoser::envelope(int agent, std::int64_t k) const {
    // The agent's disks: frames first .. last of the record's track, or of the window.
    const AgentTrack& track = record_.tracks[std::size_t(agent)];
    std::int64_t first = 0, last = std::int64_t(track.samples.size()) - 1;
    if (window_) {
        first = window_->first;
        last = std::min(window_->last, track.left_frame.value_or(record_.frames)) - 1;
        if (std::size_t(agent) < window_->agent_first || std::size_t(agent) >= window_->agent_last) last = -1;
    }
    const auto radius = [&](std::int64_t m) {
        return window_ ? window_->samples[std::size_t(m - first) * window_->width() + std::size_t(agent) -
                                          window_->agent_first][3]
                       : track.samples[std::size_t(m)][3];
    };
    k = std::min(k, last);
    if (k < first) return {std::numeric_limits<double>::infinity(), glm::dvec2(0.0)};
    // The envelope e(k) = min over k' in [k, k + look-ahead] of r(k') + pull_speed (k' - k) dt is at most
    // r(k), and a joint held inside it never needs to move inwards faster than pull_speed to stay inside
    // the frames after: where the next clip's disk is smaller than the pose it starts from, joints are
    // drawn in over the frames before rather than at once. Disks centred on the body are off the root by
    // o(k); the joints are held about the disk's centre. (The centre's sway, |o(k') - o(k)|, subtracted from
    // r(k') as well drew the joints in further: more pops and skating, bench/results/log.md, twelfth stop.)
    const bool on_root = sources_->graph().centre == io::PathCentre::Root;
    const glm::dvec2 o = on_root ? glm::dvec2(0.0) : centre_offset(agent, k);
    const std::int64_t ahead = std::int64_t(std::ceil(blend_.look_ahead / record_.dt));
    double e = radius(k);
    for (std::int64_t m = k + 1; m <= std::min(k + ahead, last); ++m)
        e = std::min(e, radius(m) + blend_.pull_speed * double(m - k) * record_.dt);
    return {e, o};
}

glm::dvec2 CrowdPoser::centre_offset(int agent, std::int64_t m) const {
    const MotionGraph& g = sources_->graph();
    AgentClipAt at;
    if (!agent_clip_at(record_, g, agent, m, at)) return glm::dvec2(0.0);
    const GraphClip& clip = g.clips[std::size_t(at.placed->clip)];
    const auto i = std::size_t(m - at.placed->start);
    const Rigid2 place = Rigid2::of(at.placed->place);
    const Sample& s = clip.path.samples[i];
    const glm::dvec2 root = placed_root(clip, place, i);
    return {place.apply_x(s.x, s.y) - root.x, place.apply_y(s.x, s.y) - root.y};
}

void CrowdPoser::hold_inside(const std::vector<int>& joints, const Envelope& e, std::vector<glm::dvec3>& out) const {
    const double cx = out[0].x + e.offset.x, cy = out[0].y + e.offset.y;
    for (int j : joints) {
        if (j == 0) continue;
        glm::dvec3& q = out[std::size_t(j)];
        const double dx = q.x - cx, dy = q.y - cy, d2 = dx * dx + dy * dy;
        if (d2 <= e.radius * e.radius) continue;
        const double f = e.radius / std::sqrt(d2);
        q = {cx + dx * f, cy + dy * f, q.z};
    }
}

bool CrowdPoser::pose_at(int agent, double t, std::vector<glm::dvec3>& out) {
    if (!(t >= 0) || !(t <= double(record_.frames) * record_.dt)) return false;
    const double f = t / record_.dt;
    std::int64_t k = std::int64_t(std::floor(f + 1e-9));
    const double u = f - double(k);
    if (k >= record_.frames) return pose(agent, record_.frames - 1, out);
    if (u < 1e-9 || k + 1 >= record_.frames) return pose(agent, k, out);
    std::vector<glm::dvec3> next;
    if (!pose(agent, k, out) || !pose(agent, k + 1, next)) return false;
    for (std::size_t j = 0; j < out.size(); ++j) out[j] += u * (next[j] - out[j]);
    return true;
}

}  // namespace mobb::crowd
