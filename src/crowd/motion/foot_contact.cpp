#include "mobb/crowd/motion/foot_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <glm/geometric.hpp>

namespace mobb::crowd {

namespace {

// Whether a joint (positions per sample) is down at each sample, with the rule's hysteresis.
std::vector<bool> joint_down(const std::vector<glm::dvec3>& p, double dt, const ContactRule& rule) {
    const std::size_t n = p.size();
    std::vector<bool> down(n, false);
    if (n == 0) return down;
    std::vector<double> h(n);
    for (std::size_t i = 0; i < n; ++i) h[i] = p[i].z;
    const std::size_t q = std::min(n - 1, std::size_t(rule.ground_quantile * double(n)));
    std::nth_element(h.begin(), h.begin() + std::ptrdiff_t(q), h.end());
    const double ground = h[q];
    bool on = false;
    for (std::size_t i = 0; i < n; ++i) {
        // Central difference, one-sided at the ends.
        const std::size_t a = i > 0 ? i - 1 : i, b = std::min(n - 1, i + 1);
        const double speed = b > a ? std::hypot(p[b].x - p[a].x, p[b].y - p[a].y) / (double(b - a) * dt) : 0.0;
        const double above = p[i].z - ground;
        on = on ? !(above > rule.height_off || speed > rule.speed_off)
                : (above < rule.height_on && speed < rule.speed_on);
        down[i] = on;
    }
    return down;
}

// Runs of `plant` that are (or are not) Free and shorter than `samples`: dropped (contacts) or filled with
// the plant before them (gaps between contacts).
void drop_short_contacts(std::vector<Plant>& plant, int samples) {
    const std::size_t n = plant.size();
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i;
        while (j < n && (plant[j] == Plant::Free) == (plant[i] == Plant::Free)) ++j;
        if (plant[i] != Plant::Free && int(j - i) < samples)
            std::fill(plant.begin() + std::ptrdiff_t(i), plant.begin() + std::ptrdiff_t(j), Plant::Free);
        i = j;
    }
}

void merge_short_gaps(std::vector<Plant>& plant, int samples) {
    const std::size_t n = plant.size();
    for (std::size_t i = 1; i < n;) {
        std::size_t j = i;
        while (j < n && plant[j] == Plant::Free) ++j;
        if (j > i && j < n && plant[i - 1] != Plant::Free && int(j - i) < samples)
            std::fill(plant.begin() + std::ptrdiff_t(i), plant.begin() + std::ptrdiff_t(j), plant[i - 1]);
        i = j + 1;
    }
}

}  // namespace

std::array<FootTrack, 2> detect_contacts(const std::array<std::vector<glm::dvec3>, 2>& heel,
                                         const std::array<std::vector<glm::dvec3>, 2>& toe, double dt,
                                         const ContactRule& rule) {
    std::array<FootTrack, 2> out;
    for (std::size_t f = 0; f < 2; ++f) {
        const std::vector<bool> h = joint_down(heel[f], dt, rule), t = joint_down(toe[f], dt, rule);
        FootTrack& track = out[f];
        track.heel = heel[f];
        track.toe = toe[f];
        track.plant.resize(h.size());
        for (std::size_t i = 0; i < h.size(); ++i)
            track.plant[i] = h[i] ? Plant::Heel : (i < t.size() && t[i] ? Plant::Toe : Plant::Free);
        drop_short_contacts(track.plant, int(std::lround(rule.min_contact / dt)));
        merge_short_gaps(track.plant, int(std::lround(rule.merge_gap / dt)));
        track.run_begin.resize(h.size());
        for (std::size_t i = 0; i < h.size(); ++i)
            track.run_begin[i] = i > 0 && track.plant[i] == track.plant[i - 1] ? track.run_begin[i - 1] : int(i);
    }
    return out;
}

std::vector<ContactSpan> clip_contacts(const std::array<FootTrack, 2>& feet, const GraphClip& clip) {
    std::vector<ContactSpan> out;
    for (int f = 0; f < 2; ++f) {
        const std::vector<Plant>& p = feet[std::size_t(f)].plant;
        const int end = std::min(clip.exit, int(p.size()));
        for (int i = std::max(clip.first, 0); i < end;) {
            int j = i;
            while (j < end && (p[std::size_t(j)] == Plant::Free) == (p[std::size_t(i)] == Plant::Free)) ++j;
            if (p[std::size_t(i)] != Plant::Free) out.push_back({f, i, j - 1});
            i = j;
        }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const ContactSpan& a, const ContactSpan& b) { return a.first < b.first; });
    return out;
}

LegSolve two_joint_ik(const glm::dvec3& hip, const glm::dvec3& knee, const glm::dvec3& ankle, const glm::dvec3& target,
                      const glm::dvec3& forward) {
    const double thigh = glm::length(knee - hip), shin = glm::length(ankle - knee);
    const glm::dvec3 to = target - hip;
    const double d = glm::length(to);
    LegSolve out;
    if (d < 1e-12) {  // the target on the hip: nothing to aim at; keep the pose
        out.knee = knee;
        out.ankle = ankle;
        out.residual = glm::length(ankle - target);
        return out;
    }
    const glm::dvec3 u = to / d;
    // The pole: the knee's offset from the hip-ankle line, else the foot's direction, else any perpendicular.
    const auto across = [&](const glm::dvec3& v) { return v - glm::dot(v, u) * u; };
    glm::dvec3 pole = knee - hip;
    if (glm::length(ankle - hip) > 1e-12) {
        const glm::dvec3 l = glm::normalize(ankle - hip);
        pole -= glm::dot(pole, l) * l;
    }
    pole = across(pole);
    if (glm::length(pole) < 1e-9 * (thigh + shin)) pole = across(forward);
    if (glm::length(pole) < 1e-12) pole = across(std::abs(u.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
    const glm::dvec3 v = glm::normalize(pole);
    // The reach clamped to what the leg spans; the knee by the law of cosines along u and towards v.
    const double reach = std::clamp(d, std::abs(thigh - shin), thigh + shin);
    const double a = (thigh * thigh - shin * shin + reach * reach) / (2.0 * reach);
    const double h = std::sqrt(std::max(0.0, thigh * thigh - a * a));
    out.knee = hip + a * u + h * v;
    out.ankle = hip + reach * u;
    out.residual = std::abs(d - reach);
    return out;
}

}  // namespace mobb::crowd
