#include "crowd_poses.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mobb/crowd/pose_distance.h"

namespace mobb::viewer {

namespace {

std::unique_ptr<PoseSource> make_source(const crowd::MotionGraph& g, int source) {
    auto out = std::make_unique<PoseSource>();
    try {
        auto clip = std::make_shared<io::Clip>(crowd::load_graph_source(g, source));
        const crowd::PoseTrack track = crowd::pose_track(*clip, crowd::select_joints(clip->animation.skeleton));
        for (int f = 0; f < track.frames; ++f) {
            out->root_x.push_back(track.root[std::size_t(f)].x);
            out->root_y.push_back(track.root[std::size_t(f)].y);
            out->heading.push_back(track.heading[std::size_t(f)]);
        }
        double lowest = 1e300;
        for (const glm::dvec3& p : clip->animation.positions) lowest = std::min(lowest, io::to_ground(p, clip->up).z);
        out->floor = clip->animation.positions.empty() ? 0.0 : lowest;
        out->clip = std::move(clip);
    } catch (const std::exception& e) {
        out->error = e.what();
    }
    return out;
}

}  // namespace

Placement source_to_world(const PoseSource& s, const crowd::GraphClip& clip, const Placement& place) {
    const std::size_t i = std::size_t(clip.first);
    if (i >= s.heading.size()) return place;
    // world = R(theta) R(-h) (p - o) + (x, y) = R(theta - h) p + (x, y) - R(theta - h) o.
    const double a = place.theta - s.heading[i];
    const double c = std::cos(a), sn = std::sin(a);
    const double ox = s.root_x[i], oy = s.root_y[i];
    return {place.x - (c * ox - sn * oy), place.y - (sn * ox + c * oy), a, place.t0};
}

bool agent_clip_at(const crowd::Record& r, const crowd::MotionGraph& g, int agent, double t, AgentClipAt& out) {
    if (agent < 0 || std::size_t(agent) >= r.tracks.size() || !(r.dt > 0)) return false;
    // The record's frame k covers [k dt, (k + 1) dt): the disk drawn at the cursor.
    const double k = std::floor(t / r.dt + 1e-9);
    if (k < 0 || k >= double(r.frames)) return false;
    const auto& clips = r.tracks[std::size_t(agent)].clips;
    // The last clip started at or before frame k (clips are in time order).
    auto it = std::upper_bound(clips.begin(), clips.end(), std::int64_t(k),
                               [](std::int64_t f, const crowd::PlacedClip& p) { return f < p.start; });
    if (it == clips.begin()) return false;
    const crowd::PlacedClip& p = *std::prev(it);
    if (p.clip < 0 || std::size_t(p.clip) >= g.clips.size()) return false;
    const crowd::GraphClip& gc = g.clips[std::size_t(p.clip)];
    const std::int64_t i = std::int64_t(k) - p.start;
    if (i >= std::int64_t(gc.exit - gc.first)) return false;
    out.placed = &p;
    out.sample = gc.first + int(i);
    return true;
}

const PoseSource& PoseSources::get(int source) {
    if (sources_.empty()) sources_.resize(graph_->sources.size());
    auto& slot = sources_.at(std::size_t(source));
    if (!slot) {
        slot = make_source(*graph_, source);
        if (!slot->error.empty() && error_.empty()) error_ = slot->error;
    }
    return *slot;
}

int PoseSources::loaded() const {
    return int(std::count_if(sources_.begin(), sources_.end(), [](const auto& s) { return s && s->clip; }));
}

std::vector<render::PosedSkeleton> crowd_skeletons(const crowd::Record& r, const crowd::MotionGraph& g,
                                                   PoseSources& sources, double t,
                                                   const std::vector<glm::vec3>& colors) {
    std::vector<render::PosedSkeleton> out;
    for (int a = 0; a < int(r.tracks.size()); ++a) {
        AgentClipAt at;
        if (!agent_clip_at(r, g, a, t, at)) continue;
        const crowd::GraphClip& gc = g.clips[std::size_t(at.placed->clip)];
        const PoseSource& src = sources.get(gc.source);
        if (!src.clip || at.sample >= src.clip->animation.frames()) continue;
        render::PosedSkeleton p;
        p.animation = &src.clip->animation;
        p.up = src.clip->up;
        p.frame = at.sample;
        p.place = source_to_world(src, gc, at.placed->place);
        p.floor = src.floor;
        // Darker than the agent's stack (the renderer darkens it once more): the skeleton stands on it.
        p.color = 0.6f * (std::size_t(a) < colors.size() ? colors[std::size_t(a)] : render::clip_color(a));
        out.push_back(p);
    }
    return out;
}

}  // namespace mobb::viewer
