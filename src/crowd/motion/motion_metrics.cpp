#include "mobb/crowd/motion/motion_metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "mobb/util/json_text.h"
#include "mobb/util/worker_pool.h"

namespace mobb::crowd {

namespace {

constexpr std::size_t kKinds = 4;  // ClipKind's values

// What one agent contributes to one MotionMetrics, merged over agents afterwards.
struct MotionTally {
    std::vector<double> start, within, knee_start, knee_within;
    std::array<std::vector<double>, kKinds> speeds, slide, residual;  // by kind
    std::array<std::size_t, kKinds> steps{};
};
struct AgentTally {
    MotionTally blended, unlocked, raw;
};

double largest_jump(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double jump = 0;  // squared until the end
    for (std::size_t j = 1; j < b.size(); ++j) {
        const glm::dvec3 d = (b[j] - b[0]) - (a[j] - a[0]);
        jump = std::max(jump, glm::dot(d, d));
    }
    return std::sqrt(jump);
}

double knee_angle(const std::vector<glm::dvec3>& p, const RigLeg& leg) {
    const glm::dvec3 thigh = p[std::size_t(leg.hip)] - p[std::size_t(leg.knee)];
    const glm::dvec3 shin = p[std::size_t(leg.ankle)] - p[std::size_t(leg.knee)];
    const double l = glm::length(thigh) * glm::length(shin);
    return l > 0 ? std::acos(std::clamp(glm::dot(thigh, shin) / l, -1.0, 1.0)) : 0.0;
}

// One frame of an agent as the tallies need it.
struct Posed {
    std::vector<glm::dvec3> pose;
    FeetAt feet;
};

// Frame k - 1 (a) to frame k (b), frame k playing a clip of kind `kind`, starting there or not. The raw
// clips' slide is their own: not across the pops at their starts.
void add_step(const Posed& a, const Posed& b, const std::array<RigLeg, 2>& legs, double dt, std::size_t kind,
              bool start, bool raw, MotionTally& out) {
    (start ? out.start : out.within).push_back(largest_jump(a.pose, b.pose));
    double knee = 0;
    for (std::size_t f = 0; f < 2; ++f) {
        const RigLeg& leg = legs[f];
        if (!leg.complete()) continue;
        knee = std::max(knee, std::abs(knee_angle(b.pose, leg) - knee_angle(a.pose, leg)));
        ++out.steps[kind];
        const glm::dvec3 &p = a.pose[std::size_t(leg.toe)], &q = b.pose[std::size_t(leg.toe)];
        if (p.z < FootContact::kHeight && q.z < FootContact::kHeight)
            out.speeds[kind].push_back(std::hypot(q.x - p.x, q.y - p.y) / dt);
        const Plant plant = b.feet.plant[f];
        if (plant != Plant::Free && a.feet.plant[f] == plant && !(start && raw)) {
            const std::size_t j = std::size_t(plant == Plant::Toe ? leg.toe : leg.ankle);
            out.slide[kind].push_back(std::hypot(b.pose[j].x - a.pose[j].x, b.pose[j].y - a.pose[j].y));
        }
        if (b.feet.held[f]) out.residual[kind].push_back(b.feet.residual[f]);
    }
    if (legs[0].complete() || legs[1].complete()) (start ? out.knee_start : out.knee_within).push_back(knee);
}

AgentTally agent_tally(CrowdPoser& poser, const std::vector<ClipKind>& kinds, int agent, std::int64_t begin,
                       std::int64_t end) {
    const Record& r = poser.record();
    const MotionGraph& g = poser.sources().graph();
    AgentTally out;
    Posed a, b, raw_a, raw_b, free_a, free_b;
    bool have = false;
    for (std::int64_t k = std::max<std::int64_t>(begin, 0); k < std::min(end, r.frames); ++k) {
        AgentClipAt at;
        if (!agent_clip_at(r, g, agent, k, at) || !poser.pose(agent, k, b.pose, raw_b.pose, free_b.pose, &b.feet)) {
            have = false;
            continue;
        }
        raw_b.feet = free_b.feet = b.feet;
        raw_b.feet.held = free_b.feet.held = {};
        if (have) {
            const auto kind = std::size_t(kinds[std::size_t(at.placed->clip)]);
            const bool start = k == at.placed->start;
            add_step(a, b, poser.legs(), r.dt, kind, start, false, out.blended);
            add_step(free_a, free_b, poser.legs(), r.dt, kind, start, false, out.unlocked);
            add_step(raw_a, raw_b, poser.legs(), r.dt, kind, start, true, out.raw);
        }
        std::swap(a, b);
        std::swap(raw_a, raw_b);
        std::swap(free_a, free_b);
        have = true;
    }
    return out;
}

template <typename T>
void append(std::vector<T>& to, const std::vector<T>& from) {
    to.insert(to.end(), from.begin(), from.end());
}

nlohmann::ordered_json spread_json(const Spread& s) {
    return {{"median", util::rounded(s.median)}, {"p99", util::rounded(s.p99)}, {"count", s.count}};
}

nlohmann::ordered_json metrics_object(const MotionMetrics& m) {
    using Json = nlohmann::ordered_json;
    Json j{{"blend", m.blend},
           {"jump_start", spread_json(m.jump_start)},
           {"jump_within", spread_json(m.jump_within)},
           {"jump_ratio", util::rounded(m.jump_ratio(), 4)}};
    if (m.locked) j["feet_locked"] = true;
    if (!m.feet) return j;
    j["knee_start"] = spread_json(m.knee_start);
    j["knee_within"] = spread_json(m.knee_within);
    j["knee_ratio"] = util::rounded(m.knee_ratio(), 4);
    Json sliding = Json::object(), hold = Json::object();
    for (std::size_t k = 0; k < kKinds; ++k) {
        const FootSliding& s = m.sliding[k];
        sliding[to_string(ClipKind(k))] = {{"steps", s.steps},
                                           {"contact", s.contact},
                                           {"speed", spread_json(s.speed)},
                                           {"skate_share", util::rounded(s.skate_share, 4)}};
        hold[to_string(ClipKind(k))] = {{"slide", spread_json(m.hold[k].slide)},
                                        {"residual", spread_json(m.hold[k].residual)}};
    }
    j["foot_sliding"] = sliding;
    j["foot_contacts"] = hold;
    return j;
}

std::string metrics_line(const char* what, const MotionMetrics& m) {
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(3);
    out << "  " << what << ": joint jump median / p99 " << m.jump_start.median << " / " << m.jump_start.p99 << " m at "
        << m.jump_start.count << " clip starts, " << m.jump_within.median << " / " << m.jump_within.p99
        << " m within clips; p99 ratio " << std::setprecision(2) << m.jump_ratio() << "\n";
    if (!m.feet) return out.str() + "  (no legs: no foot sliding)\n";
    out << "    knee angle jump median / p99 " << std::setprecision(3) << m.knee_start.median << " / "
        << m.knee_start.p99 << " rad at clip starts, " << m.knee_within.median << " / " << m.knee_within.p99
        << " rad within clips; p99 ratio " << std::setprecision(2) << m.knee_ratio() << "\n";
    out << "    foot sliding in contact, median / p99 m/s, skating %:";
    for (std::size_t k = 0; k < kKinds; ++k) {
        const FootSliding& s = m.sliding[k];
        if (s.steps == 0) continue;
        out << " " << to_string(ClipKind(k)) << " " << std::setprecision(3) << s.speed.median << " / " << s.speed.p99
            << ", " << std::setprecision(1) << 100 * s.skate_share << ";";
    }
    out << "\n    planted feet (found contacts), slide p99 cm per frame, IK residual p99 cm:";
    for (std::size_t k = 0; k < kKinds; ++k) {
        if (m.sliding[k].steps == 0) continue;
        out << " " << to_string(ClipKind(k)) << " " << std::setprecision(2) << 100 * m.hold[k].slide.p99 << ", "
            << 100 * m.hold[k].residual.p99 << ";";
    }
    return out.str() + "\n";
}

}  // namespace

Spread spread_of(std::vector<double>& v) {
    Spread s;
    s.count = v.size();
    if (v.empty()) return s;
    const auto at = [&](double q) {
        const std::size_t n = std::min(v.size() - 1, std::size_t(std::ceil(q * double(v.size()))) - 1);
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(n), v.end());
        return v[n];
    };
    s.median = at(0.5);
    s.p99 = at(0.99);
    return s;
}

namespace {

MotionMetrics merged(const std::vector<AgentTally>& tallies, MotionTally AgentTally::*which, bool feet) {
    MotionMetrics m;
    m.feet = feet;
    std::vector<double> start, within, knee_start, knee_within;
    for (const AgentTally& s : tallies) {
        append(start, (s.*which).start);
        append(within, (s.*which).within);
        append(knee_start, (s.*which).knee_start);
        append(knee_within, (s.*which).knee_within);
    }
    m.jump_start = spread_of(start);
    m.jump_within = spread_of(within);
    if (!feet) return m;
    m.knee_start = spread_of(knee_start);
    m.knee_within = spread_of(knee_within);
    for (std::size_t k = 0; k < kKinds; ++k) {
        std::vector<double> speeds, slide, residual;
        FootSliding& f = m.sliding[k];
        for (const AgentTally& s : tallies) {
            append(speeds, (s.*which).speeds[k]);
            append(slide, (s.*which).slide[k]);
            append(residual, (s.*which).residual[k]);
            f.steps += (s.*which).steps[k];
        }
        m.hold[k].slide = spread_of(slide);
        m.hold[k].residual = spread_of(residual);
        f.contact = speeds.size();
        const auto skating =
            std::count_if(speeds.begin(), speeds.end(), [](double v) { return v > FootContact::kSkateSpeed; });
        f.skate_share = speeds.empty() ? 0.0 : double(skating) / double(speeds.size());
        f.speed = spread_of(speeds);
    }
    return m;
}

}  // namespace

CrowdMotion motion_metrics(CrowdPoser& poser, const std::vector<int>& agents, std::int64_t frame_begin,
                           std::int64_t frame_end, int threads) {
    const auto t0 = std::chrono::steady_clock::now();
    const MotionGraph& g = poser.sources().graph();
    const std::vector<ClipKind> kinds = kinds_of(g);
    std::vector<AgentTally> tallies(agents.size());
    // Each worker poses with its own copy (a poser's scratch is its own; the loaded sources are shared).
    util::WorkerPool pool(std::max(1, std::min(threads, int(agents.size()))));
    std::vector<CrowdPoser> posers(std::size_t(pool.size()), poser);
    pool.for_each(agents.size(), [&](std::size_t i, int worker) {
        tallies[i] = agent_tally(posers[std::size_t(worker)], kinds, agents[i], frame_begin, frame_end);
    });
    const bool both = poser.legs()[0].complete() && poser.legs()[1].complete();
    CrowdMotion out;
    out.blended = merged(tallies, &AgentTally::blended, both);
    out.unlocked = merged(tallies, &AgentTally::unlocked, both);
    out.raw = merged(tallies, &AgentTally::raw, both);
    out.blended.joints = out.unlocked.joints = out.raw.joints = poser.rig().size();
    out.blended.blend = out.unlocked.blend = poser.blend().window;
    out.blended.locked = poser.lock().on;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

CrowdMotion crowd_motion(const Record& record, std::shared_ptr<const MotionGraph> graph, double blend, int threads,
                         bool lock_feet) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<int> agents(record.tracks.size());
    for (std::size_t i = 0; i < agents.size(); ++i) agents[i] = int(i);
    PoseBlend b;
    b.window = blend;
    FootLock lock;
    lock.on = lock_feet;
    CrowdPoser poser(record, std::make_shared<PoseSources>(std::move(graph)), RigJoints::All, b, lock);
    CrowdMotion out = motion_metrics(poser, agents, 0, record.frames, threads);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

std::string motion_json(const CrowdMotion& m) {
    using Json = nlohmann::ordered_json;
    Json j{{"joints", m.blended.joints},
           {"foot_contact",
            {{"toe", FootContact::kToe}, {"height", FootContact::kHeight}, {"skate_speed", FootContact::kSkateSpeed}}},
           {"blended", metrics_object(m.blended)},
           {"unlocked", metrics_object(m.unlocked)},
           {"raw", metrics_object(m.raw)}};
    return j.dump();
}

std::string motion_text(const CrowdMotion& m) {
    std::ostringstream out;
    out << "motion (" << m.blended.joints << " joints; foot contact: toe below " << FootContact::kHeight
        << " m, skating above " << FootContact::kSkateSpeed << " m/s; " << std::fixed << std::setprecision(1)
        << m.seconds << " s to measure):\n"
        << metrics_line(("blended " + util::fixed(m.blended.blend, 2) + " s" +
                         (m.blended.locked ? ", feet locked" : ", feet free"))
                            .c_str(),
                        m.blended)
        << metrics_line("blended, feet free", m.unlocked) << metrics_line("raw clips", m.raw);
    return out.str();
}

std::string with_motion(const std::string& metrics_json, const CrowdMotion& m) {
    auto j = nlohmann::ordered_json::parse(metrics_json);
    j["motion"] = nlohmann::ordered_json::parse(motion_json(m));
    return j.dump();
}

}  // namespace mobb::crowd
