#include "mobb/crowd/graph/pose_distance.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace mobb::crowd {

namespace {

// Major joints by name ending, with weights: legs and trunk decide a transition more than fingers.
struct NamedJoint {
    const char* suffix;
    double weight;
};
constexpr NamedJoint kMajor[] = {
    {"Pelvis", 1.0},     {"L_Thigh", 1.0},   {"R_Thigh", 1.0},   {"L_Calf", 1.0},  {"R_Calf", 1.0}, {"L_Foot", 1.0},
    {"R_Foot", 1.0},     {"L_ToeBase", 0.5}, {"R_ToeBase", 0.5}, {"Spine02", 1.0}, {"Head", 1.0},   {"L_Upperarm", 0.5},
    {"R_Upperarm", 0.5}, {"L_Forearm", 0.5}, {"R_Forearm", 0.5}, {"L_Hand", 0.5},  {"R_Hand", 0.5},
};

bool ends_with_joint(const std::string& name, const std::string& suffix) {
    if (name.size() < suffix.size()) return false;
    if (name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
    return name.size() == suffix.size() || name[name.size() - suffix.size() - 1] == '_';
}

int find_joint(const io::Skeleton& s, const std::string& suffix) {
    for (int j = 0; j < s.size(); ++j)
        if (!s.end_site[std::size_t(j)] && ends_with_joint(s.names[std::size_t(j)], suffix)) return j;
    return -1;
}

int window_start(int f, int frames, int w) { return std::clamp(f - w / 2, 0, frames - w); }

// Weighted sums of one frame (or window) needed by the closed-form alignment.
struct FrameSums {
    double w = 0;       // total weight
    glm::dvec2 s{0.0};  // sum w p
    double ss = 0;      // sum w |p|^2 (ground)
    double hh = 0;      // sum w h^2
};

// Cross sums of a frame pair: sum w a.b, sum w (b x a), sum w ha hb.
struct PairSums {
    double dot = 0, cross = 0, hh = 0;
};

FrameSums frame_sums(const PoseTrack& t, int f) {
    FrameSums out;
    for (int j = 0; j < t.joints; ++j) {
        const glm::dvec3& p = t.points[std::size_t(f) * t.joints + j];
        const double w = t.weights[std::size_t(j)];
        out.w += w;
        out.s += w * glm::dvec2(p.x, p.y);
        out.ss += w * (p.x * p.x + p.y * p.y);
        out.hh += w * p.z * p.z;
    }
    return out;
}

PairSums pair_sums(const PoseTrack& a, int fa, const PoseTrack& b, int fb) {
    PairSums out;
    const glm::dvec3* pa = &a.points[std::size_t(fa) * a.joints];
    const glm::dvec3* pb = &b.points[std::size_t(fb) * b.joints];
    for (int j = 0; j < a.joints; ++j) {
        const double w = a.weights[std::size_t(j)];
        out.dot += w * (pa[j].x * pb[j].x + pa[j].y * pb[j].y);
        out.cross += w * (pb[j].x * pa[j].y - pb[j].y * pa[j].x);
        out.hh += w * pa[j].z * pb[j].z;
    }
    return out;
}

// Procrustes in the plane: minimise sum w |a - (R b + t)|^2 + sum w (ha - hb)^2 over R, t.
PoseMatch solve(const FrameSums& a, const FrameSums& b, const PairSums& ab) {
    const double w = a.w;
    const double dot = ab.dot - glm::dot(a.s, b.s) / w;
    const double cross = ab.cross - (b.s.x * a.s.y - b.s.y * a.s.x) / w;
    const double aa = a.ss - glm::dot(a.s, a.s) / w;
    const double bb = b.ss - glm::dot(b.s, b.s) / w;
    const double heights = a.hh + b.hh - 2.0 * ab.hh;
    const double sq = aa + bb - 2.0 * std::hypot(dot, cross) + heights;
    PoseMatch m;
    m.distance = std::sqrt(std::max(0.0, sq) / w);
    m.theta = std::atan2(cross, dot);
    const double c = std::cos(m.theta), s = std::sin(m.theta);
    m.shift = (a.s - glm::dvec2(c * b.s.x - s * b.s.y, s * b.s.x + c * b.s.y)) / w;
    return m;
}

void add(FrameSums& to, const FrameSums& x) {
    to.w += x.w;
    to.s += x.s;
    to.ss += x.ss;
    to.hh += x.hh;
}

void add(PairSums& to, const PairSums& x) {
    to.dot += x.dot;
    to.cross += x.cross;
    to.hh += x.hh;
}

// Facing at frame f from left/right joint pairs (lr: l0, r0, l1, r1, ...) of the ground positions.
double facing_at(const std::vector<glm::dvec3>& ground, int joints, const std::vector<int>& lr, int f) {
    glm::dvec2 d(0.0);
    for (std::size_t k = 0; k + 1 < lr.size(); k += 2) {
        const glm::dvec3& l = ground[std::size_t(f) * std::size_t(joints) + std::size_t(lr[k])];
        const glm::dvec3& r = ground[std::size_t(f) * std::size_t(joints) + std::size_t(lr[k + 1])];
        d += glm::dvec2(l.x - r.x, l.y - r.y);
    }
    return std::atan2(-d.x, d.y);  // front = left-minus-right turned by -90 degrees
}

}  // namespace

PoseJoints select_joints(const io::Skeleton& skeleton) {
    PoseJoints out;
    out.joints.push_back(skeleton.root);
    out.weights.push_back(1.0);
    out.names.push_back(skeleton.names[std::size_t(skeleton.root)]);
    for (const NamedJoint& nj : kMajor) {
        const int j = find_joint(skeleton, nj.suffix);
        if (j < 0 || j == skeleton.root) continue;
        out.joints.push_back(j);
        out.weights.push_back(nj.weight);
        out.names.push_back(skeleton.names[std::size_t(j)]);
    }
    if (out.joints.size() >= 6) return out;
    out = {};
    for (int j = 0; j < skeleton.size(); ++j) {
        out.joints.push_back(j);
        out.weights.push_back(1.0);
        out.names.push_back(skeleton.names[std::size_t(j)]);
    }
    return out;
}

PoseTrack pose_track(const io::Clip& clip, const PoseJoints& joints) {
    const io::Animation& anim = clip.animation;
    PoseTrack t;
    t.dt = anim.dt;
    t.frames = anim.frames();
    t.joints = int(joints.joints.size());
    t.weights = joints.weights;
    t.points.reserve(std::size_t(t.frames) * std::size_t(t.joints));
    for (int f = 0; f < t.frames; ++f)
        for (int j : joints.joints) t.points.push_back(io::to_ground(anim.at(f, j), clip.up));
    for (const Sample& s : clip.path.samples) t.root.emplace_back(s.x, s.y);

    // Left/right pairs for the facing direction, looked up among every joint (not only the compared ones).
    std::vector<int> lr;
    for (const char* side : {"Thigh", "Upperarm"}) {
        const int l = find_joint(anim.skeleton, std::string("L_") + side);
        const int r = find_joint(anim.skeleton, std::string("R_") + side);
        if (l >= 0 && r >= 0) {
            lr.push_back(l);
            lr.push_back(r);
        }
    }
    if (!lr.empty()) {
        std::vector<glm::dvec3> ground;
        ground.reserve(anim.positions.size());
        for (const glm::dvec3& p : anim.positions) ground.push_back(io::to_ground(p, clip.up));
        std::vector<double> raw;
        raw.reserve(std::size_t(t.frames));
        for (int f = 0; f < t.frames; ++f) raw.push_back(facing_at(ground, anim.skeleton.size(), lr, f));
        for (int f = 0; f < t.frames; ++f) {
            glm::dvec2 sum(0.0);
            for (int k = std::max(0, f - 2); k <= std::min(t.frames - 1, f + 2); ++k)
                sum += glm::dvec2(std::cos(raw[std::size_t(k)]), std::sin(raw[std::size_t(k)]));
            t.heading.push_back(std::atan2(sum.y, sum.x));
        }
        return t;
    }
    for (int f = 0; f < t.frames; ++f) {
        const glm::dvec2 d =
            t.root[std::size_t(std::min(t.frames - 1, f + 2))] - t.root[std::size_t(std::max(0, f - 2))];
        t.heading.push_back(glm::dot(d, d) > 0 ? std::atan2(d.y, d.x) : 0.0);
    }
    return t;
}

PoseMatch pose_distance(const PoseTrack& a, int fa, const PoseTrack& b, int fb, int window) {
    const int w = std::max(1, std::min({window, a.frames, b.frames}));
    const int sa = window_start(fa, a.frames, w), sb = window_start(fb, b.frames, w);
    FrameSums fa_sums, fb_sums;
    PairSums ab;
    for (int k = 0; k < w; ++k) {
        add(fa_sums, frame_sums(a, sa + k));
        add(fb_sums, frame_sums(b, sb + k));
        add(ab, pair_sums(a, sa + k, b, sb + k));
    }
    return solve(fa_sums, fb_sums, ab);
}

std::vector<float> distance_matrix(const PoseTrack& a, const PoseTrack& b, int window) {
    const int w = std::max(1, std::min({window, a.frames, b.frames}));
    std::vector<FrameSums> sa, sb;
    for (int f = 0; f < a.frames; ++f) sa.push_back(frame_sums(a, f));
    for (int f = 0; f < b.frames; ++f) sb.push_back(frame_sums(b, f));
    std::vector<PairSums> pairs(std::size_t(a.frames) * std::size_t(b.frames));
    for (int i = 0; i < a.frames; ++i)
        for (int j = 0; j < b.frames; ++j)
            pairs[std::size_t(i) * std::size_t(b.frames) + std::size_t(j)] = pair_sums(a, i, b, j);
    std::vector<float> out(pairs.size());
    for (int i = 0; i < a.frames; ++i) {
        const int si = window_start(i, a.frames, w);
        for (int j = 0; j < b.frames; ++j) {
            const int sj = window_start(j, b.frames, w);
            FrameSums x, y;
            PairSums xy;
            for (int k = 0; k < w; ++k) {
                const std::size_t ak = std::size_t(si) + std::size_t(k), bk = std::size_t(sj) + std::size_t(k);
                add(x, sa[ak]);
                add(y, sb[bk]);
                add(xy, pairs[ak * std::size_t(b.frames) + bk]);
            }
            out[std::size_t(i) * std::size_t(b.frames) + std::size_t(j)] = float(solve(x, y, xy).distance);
        }
    }
    return out;
}

}  // namespace mobb::crowd
