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
    std::vector<double> start, within;
    std::array<std::vector<double>, kKinds> speeds;  // in contact, by kind
    std::array<std::size_t, kKinds> steps{};
};
struct AgentTally {
    MotionTally blended, raw;
};

bool ends_with(const std::string& name, const std::string& suffix) {
    return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The rig's left and right toe joints (names ending "L_ToeBase", "R_ToeBase"); -1 where absent.
std::array<int, 2> toes(const Rig& rig) {
    std::array<int, 2> out{-1, -1};
    for (int j = 0; j < rig.size(); ++j)
        for (int side = 0; side < 2; ++side)
            if (out[std::size_t(side)] < 0 &&
                ends_with(rig.names[std::size_t(j)], std::string(side ? "R_" : "L_") + FootContact::kToe))
                out[std::size_t(side)] = j;
    return out;
}

double largest_jump(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double jump = 0;  // squared until the end
    for (std::size_t j = 1; j < b.size(); ++j) {
        const glm::dvec3 d = (b[j] - b[0]) - (a[j] - a[0]);
        jump = std::max(jump, glm::dot(d, d));
    }
    return std::sqrt(jump);
}

// Frame k - 1 (a) to frame k (b), frame k playing a clip of kind `kind`, starting there or not.
void add_step(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b, const std::array<int, 2>& feet,
              double dt, std::size_t kind, bool start, MotionTally& out) {
    (start ? out.start : out.within).push_back(largest_jump(a, b));
    for (int f : feet) {
        if (f < 0) continue;
        ++out.steps[kind];
        const glm::dvec3 &p = a[std::size_t(f)], &q = b[std::size_t(f)];
        if (p.z < FootContact::kHeight && q.z < FootContact::kHeight)
            out.speeds[kind].push_back(std::hypot(q.x - p.x, q.y - p.y) / dt);
    }
}

AgentTally agent_tally(CrowdPoser& poser, const std::vector<ClipKind>& kinds, const std::array<int, 2>& feet, int agent,
                       std::int64_t begin, std::int64_t end) {
    const Record& r = poser.record();
    const MotionGraph& g = poser.sources().graph();
    AgentTally out;
    std::vector<glm::dvec3> a, b, raw_a, raw_b;
    bool have = false;
    for (std::int64_t k = std::max<std::int64_t>(begin, 0); k < std::min(end, r.frames); ++k) {
        AgentClipAt at;
        if (!agent_clip_at(r, g, agent, k, at) || !poser.pose(agent, k, b, raw_b)) {
            have = false;
            continue;
        }
        if (have) {
            const auto kind = std::size_t(kinds[std::size_t(at.placed->clip)]);
            const bool start = k == at.placed->start;
            add_step(a, b, feet, r.dt, kind, start, out.blended);
            add_step(raw_a, raw_b, feet, r.dt, kind, start, out.raw);
        }
        std::swap(a, b);
        std::swap(raw_a, raw_b);
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
    if (!m.feet) return j;
    Json sliding = Json::object();
    for (std::size_t k = 0; k < kKinds; ++k) {
        const FootSliding& s = m.sliding[k];
        sliding[to_string(ClipKind(k))] = {{"steps", s.steps},
                                           {"contact", s.contact},
                                           {"speed", spread_json(s.speed)},
                                           {"skate_share", util::rounded(s.skate_share, 4)}};
    }
    j["foot_sliding"] = sliding;
    return j;
}

std::string metrics_line(const char* what, const MotionMetrics& m) {
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(3);
    out << "  " << what << ": joint jump median / p99 " << m.jump_start.median << " / " << m.jump_start.p99 << " m at "
        << m.jump_start.count << " clip starts, " << m.jump_within.median << " / " << m.jump_within.p99
        << " m within clips; p99 ratio " << std::setprecision(2) << m.jump_ratio() << "\n";
    if (!m.feet) return out.str() + "  (no toe joints: no foot sliding)\n";
    out << "    foot sliding in contact, median / p99 m/s, skating %:";
    for (std::size_t k = 0; k < kKinds; ++k) {
        const FootSliding& s = m.sliding[k];
        if (s.steps == 0) continue;
        out << " " << to_string(ClipKind(k)) << " " << std::setprecision(3) << s.speed.median << " / " << s.speed.p99
            << ", " << std::setprecision(1) << 100 * s.skate_share << ";";
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
    std::vector<double> start, within;
    for (const AgentTally& s : tallies) {
        append(start, (s.*which).start);
        append(within, (s.*which).within);
    }
    m.jump_start = spread_of(start);
    m.jump_within = spread_of(within);
    if (!feet) return m;
    for (std::size_t k = 0; k < kKinds; ++k) {
        std::vector<double> speeds;
        FootSliding& f = m.sliding[k];
        for (const AgentTally& s : tallies) {
            append(speeds, (s.*which).speeds[k]);
            f.steps += (s.*which).steps[k];
        }
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
    std::vector<ClipKind> kinds;
    for (std::size_t c = 0; c < g.clips.size(); ++c) kinds.push_back(kind_of(g.clips[c], int(c)));
    const std::array<int, 2> feet = toes(poser.rig());
    std::vector<AgentTally> tallies(agents.size());
    // Each worker poses with its own copy (a poser's scratch is its own; the loaded sources are shared).
    util::WorkerPool pool(std::max(1, std::min(threads, int(agents.size()))));
    std::vector<CrowdPoser> posers(std::size_t(pool.size()), poser);
    pool.for_each(agents.size(), [&](std::size_t i, int worker) {
        tallies[i] = agent_tally(posers[std::size_t(worker)], kinds, feet, agents[i], frame_begin, frame_end);
    });
    const bool both = feet[0] >= 0 && feet[1] >= 0;
    CrowdMotion out;
    out.blended = merged(tallies, &AgentTally::blended, both);
    out.raw = merged(tallies, &AgentTally::raw, both);
    out.blended.joints = out.raw.joints = poser.rig().size();
    out.blended.blend = poser.blend().window;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

CrowdMotion crowd_motion(const Record& record, std::shared_ptr<const MotionGraph> graph, double blend, int threads) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<int> agents(record.tracks.size());
    for (std::size_t i = 0; i < agents.size(); ++i) agents[i] = int(i);
    PoseBlend b;
    b.window = blend;
    CrowdPoser poser(record, std::make_shared<PoseSources>(std::move(graph)), RigJoints::All, b);
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
           {"raw", metrics_object(m.raw)}};
    return j.dump();
}

std::string motion_text(const CrowdMotion& m) {
    std::ostringstream out;
    out << "motion (" << m.blended.joints << " joints; foot contact: toe below " << FootContact::kHeight
        << " m, skating above " << FootContact::kSkateSpeed << " m/s; " << std::fixed << std::setprecision(1)
        << m.seconds << " s to measure):\n"
        << metrics_line(("blended " + util::fixed(m.blended.blend, 2) + " s").c_str(), m.blended)
        << metrics_line("raw clips", m.raw);
    return out.str();
}

std::string with_motion(const std::string& metrics_json, const CrowdMotion& m) {
    auto j = nlohmann::ordered_json::parse(metrics_json);
    j["motion"] = nlohmann::ordered_json::parse(motion_json(m));
    return j.dump();
}

}  // namespace mobb::crowd
