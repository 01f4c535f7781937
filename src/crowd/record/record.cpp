#include "mobb/crowd/record/record.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "mobb/crowd/record/record_reader.h"
#include "record/frame_grid.h"

namespace mobb::crowd {

const char* to_string(AtGoal at_goal) { return at_goal == AtGoal::Leave ? "leave" : "stay"; }

std::optional<AtGoal> at_goal_of(const std::string& name) {
    if (name == "stay") return AtGoal::Stay;
    if (name == "leave") return AtGoal::Leave;
    return std::nullopt;
}

namespace {

// Whether agent a plays a fallback clip at frame f (clips are in time order).
bool fallback_at(const AgentTrack& t, std::int64_t f) {
    auto it = std::upper_bound(t.clips.begin(), t.clips.end(), f,
                               [](std::int64_t x, const PlacedClip& c) { return x < c.start; });
    return it != t.clips.begin() && std::prev(it)->fallback;
}

}  // namespace

std::vector<Contact> frame_contacts(const Record& record) {
    const std::size_t n = record.tracks.size();
    std::vector<Contact> out;
    if (n < 2) return out;
    // The samples are stored per agent; frames are scanned a block at a time from a frame-major copy,
    // so every track is read in runs rather than one cache line per agent per frame.
    constexpr std::int64_t kBlock = 32;
    std::vector<FrameGrid::Disk> block(std::size_t(kBlock) * n);
    std::vector<std::size_t> in_run;
    FrameGrid grid;
    const auto by_pair = [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
    for (std::int64_t f0 = 0; f0 < record.frames; f0 += kBlock) {
        const std::int64_t frames = std::min(kBlock, record.frames - f0);
        double rmax = 0;                        // of the block: contacts are closer than 2 rmax
        in_run.assign(std::size_t(frames), 0);  // per frame: agents still in the run (none left yet)
        for (std::size_t a = 0; a < n; ++a) {
            const auto& samples = record.tracks[a].samples;
            const std::int64_t until = std::min(frames, std::int64_t(samples.size()) - f0);
            for (std::int64_t k = 0; k < until; ++k) {
                const auto& s = samples[std::size_t(f0 + k)];
                block[std::size_t(k) * n + in_run[std::size_t(k)]++] = {s[1], s[2], s[3], int(a)};
                rmax = std::max(rmax, s[3]);
            }
        }
        for (std::int64_t k = 0; k < frames; ++k) {
            const std::int64_t f = f0 + k;
            grid.build(&block[std::size_t(k) * n], in_run[std::size_t(k)], 2 * rmax);
            const std::size_t first = out.size();
            grid.overlaps([&](int a, int b) { out.push_back({f, std::min(a, b), std::max(a, b), false}); });
            std::sort(out.begin() + std::ptrdiff_t(first), out.end(), by_pair);
            for (std::size_t c = first; c < out.size(); ++c)
                out[c].excused = fallback_at(record.tracks[std::size_t(out[c].a)], f) ||
                                 fallback_at(record.tracks[std::size_t(out[c].b)], f);
        }
    }
    return out;
}

std::vector<Contact> frame_contacts(const SampleWindow& w, const Record& header) {
    std::vector<Contact> out;
    std::vector<FrameGrid::Disk> in_run;
    FrameGrid grid;
    const auto by_pair = [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
    for (std::int64_t f = w.first; f < w.last; ++f) {
        in_run.clear();
        double rmax = 0;  // contacts are closer than 2 rmax
        for (std::size_t i = 0; i < w.width(); ++i) {
            const std::array<double, 4>& d = w.samples[std::size_t(f - w.first) * w.width() + i];
            if (std::isnan(d[0])) continue;
            in_run.push_back({d[1], d[2], d[3], int(w.agent_first + i)});
            rmax = std::max(rmax, d[3]);
        }
        if (in_run.size() < 2) continue;
        grid.build(in_run.data(), in_run.size(), 2 * rmax);
        const std::size_t first = out.size();
        grid.overlaps([&](int a, int b) { out.push_back({f, std::min(a, b), std::max(a, b), false}); });
        std::sort(out.begin() + std::ptrdiff_t(first), out.end(), by_pair);
        for (std::size_t c = first; c < out.size(); ++c)
            out[c].excused = fallback_at(header.tracks.at(std::size_t(out[c].a)), f) ||
                             fallback_at(header.tracks.at(std::size_t(out[c].b)), f);
    }
    return out;
}

namespace {

// The escape clips and held ground choice point `cp` reserved for `agent`: its own or a reroute's.
struct ReservedPlan {
    const std::vector<FramedClip>* escape = nullptr;
    std::optional<HeldGround> hold;
};

ReservedPlan reserved_plan(const ChoicePoint& cp, int agent) {
    if (agent == cp.agent) {
        ReservedPlan p{&cp.escape, std::nullopt};
        if (cp.holds) p.hold = HeldGround{cp.hold, cp.hold_frame};
        return p;
    }
    for (const ReroutedPlan& r : cp.reroutes)
        if (r.agent == agent) return {&r.escape, HeldGround{r.hold, r.hold_frame}};
    throw std::out_of_range("no plan of that agent at that choice point");
}

}  // namespace

std::optional<FramedClip> query_clip(const Record& r, const CandidateQuery& q) {
    if (q.agent < 0 || q.piece < 0) return std::nullopt;
    return query_clip(r, q, q.piece > 0 ? &r.choices.at(std::size_t(q.choice)) : nullptr);
}

std::optional<FramedClip> query_clip(const Record& r, const CandidateQuery& q, const ChoicePoint* named) {
    if (q.agent < 0 || q.piece < 0) return std::nullopt;
    if (q.piece > 0) {
        if (!named) throw std::out_of_range("the choice point the query names is not at hand");
        return reserved_plan(*named, q.agent).escape->at(std::size_t(q.piece - 1));
    }
    const auto& clips = r.tracks.at(std::size_t(q.agent)).clips;
    const auto it = std::lower_bound(clips.begin(), clips.end(), std::int64_t(q.choice),
                                     [](const PlacedClip& c, std::int64_t x) { return c.choice < x; });
    if (it == clips.end() || it->choice != q.choice) throw std::out_of_range("no clip of that choice point");
    return FramedClip{it->clip, it->start, it->place};
}

std::optional<HeldGround> query_hold(const Record& r, const CandidateQuery& q) {
    if (q.agent < 0 || q.piece != -1 || q.choice < 0) return std::nullopt;
    const std::optional<HeldGround> h = reserved_plan(r.choices.at(std::size_t(q.choice)), q.agent).hold;
    if (!h) throw std::out_of_range("no held ground in that plan");
    return h;
}
}  // namespace mobb::crowd
