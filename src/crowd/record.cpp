#include "mobb/crowd/record.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "mobb/util/json_text.h"

namespace mobb::crowd {

namespace {

// Whether agent a plays a fallback clip at frame f (clips are in time order).
bool fallback_at(const AgentTrack& t, std::int64_t f) {
    auto it = std::upper_bound(t.clips.begin(), t.clips.end(), f,
                               [](std::int64_t x, const PlacedClip& c) { return x < c.start; });
    return it != t.clips.begin() && std::prev(it)->fallback;
}

// The agents of one frame sorted into a flat grid over their bounding rectangle (a counting sort, so
// linear in the agents), their disks stored in cell order so that scans read contiguous memory. Cells
// are wider than any contact distance, so contacts are between agents of neighbouring cells, and there
// are at most about 2 n cells however far agents stray.
class FrameGrid {
public:
    struct Disk {
        double x, y, r;
        int agent;
    };

    /// Sorts the disks of one frame, `frame[a]` for agent a (frame[a].agent == a).
    void build(const Disk* frame, std::size_t n, double reach) {
        x0_ = y0_ = 1e300;
        double x1 = -1e300, y1 = -1e300;
        for (std::size_t a = 0; a < n; ++a)
            x0_ = std::min(x0_, frame[a].x), y0_ = std::min(y0_, frame[a].y), x1 = std::max(x1, frame[a].x),
            y1 = std::max(y1, frame[a].y);
        const double w = x1 - x0_, h = y1 - y0_, count = double(n);
        // The margin keeps rounding of (x - x0) / cell from putting two agents closer than `reach` two
        // cells apart.
        cell_ = std::max({reach * (1 + 1e-9), std::sqrt(w * h / count), (w + h) / count, 1e-6});
        nx_ = int(w / cell_) + 1, ny_ = int(h / cell_) + 1;
        cell_of_.resize(n);
        first_.assign(std::size_t(nx_) * std::size_t(ny_) + 1, 0);
        for (std::size_t a = 0; a < n; ++a) {
            cell_of_[a] = cell(column(frame[a].x - x0_, nx_), column(frame[a].y - y0_, ny_));
            ++first_[cell_of_[a] + 1];
        }
        for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
        disks_.resize(n);
        fill_.assign(first_.begin(), first_.end() - 1);
        for (std::size_t a = 0; a < n; ++a) disks_[fill_[cell_of_[a]]++] = frame[a];
    }

    /// Calls f(a, b) once for every unordered pair of agents whose disks overlap (|p_a - p_b| < r_a + r_b).
    template <class F>
    void overlaps(F&& f) const {
        for (int ix = 0; ix < nx_; ++ix)
            for (int iy = 0; iy < ny_; ++iy) {
                const std::size_t c = cell(ix, iy);
                for (std::size_t i = first_[c]; i < first_[c + 1]; ++i) {
                    test(i, i + 1, first_[c + 1], f);                            // the rest of its cell
                    if (iy + 1 < ny_) test(i, first_[c + 1], first_[c + 2], f);  // the cell above
                    if (ix + 1 < nx_) {                                          // the three cells to the right
                        const std::size_t lo = cell(ix + 1, std::max(0, iy - 1)),
                                          hi = cell(ix + 1, std::min(ny_ - 1, iy + 1));
                        test(i, first_[lo], first_[hi + 1], f);
                    }
                }
            }
    }

private:
    int column(double d, int n) const { return std::clamp(int(d / cell_), 0, n - 1); }
    std::size_t cell(int ix, int iy) const { return std::size_t(ix) * std::size_t(ny_) + std::size_t(iy); }

    template <class F>
    void test(std::size_t i, std::size_t lo, std::size_t hi, F& f) const {
        const Disk& a = disks_[i];
        for (std::size_t j = lo; j < hi; ++j) {
            const Disk& b = disks_[j];
            const double dx = a.x - b.x, dy = a.y - b.y, r = a.r + b.r;
            if (dx * dx + dy * dy < r * r) f(a.agent, b.agent);
        }
    }

    double x0_ = 0, y0_ = 0, cell_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::size_t> cell_of_, first_, fill_;
    std::vector<Disk> disks_;
};

}  // namespace

std::vector<Contact> frame_contacts(const Record& record) {
    const std::size_t n = record.tracks.size();
    std::vector<Contact> out;
    if (n < 2) return out;
    // The samples are stored per agent; frames are scanned a block at a time from a frame-major copy,
    // so every track is read in runs rather than one cache line per agent per frame.
    constexpr std::int64_t kBlock = 32;
    std::vector<FrameGrid::Disk> block(std::size_t(kBlock) * n);
    FrameGrid grid;
    const auto by_pair = [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
    for (std::int64_t f0 = 0; f0 < record.frames; f0 += kBlock) {
        const std::int64_t frames = std::min(kBlock, record.frames - f0);
        double rmax = 0;  // of the block: contacts are closer than 2 rmax
        for (std::size_t a = 0; a < n; ++a)
            for (std::int64_t k = 0; k < frames; ++k) {
                const auto& s = record.tracks[a].samples[std::size_t(f0 + k)];
                block[std::size_t(k) * n + a] = {s[1], s[2], s[3], int(a)};
                rmax = std::max(rmax, s[3]);
            }
        for (std::int64_t k = 0; k < frames; ++k) {
            const std::int64_t f = f0 + k;
            grid.build(&block[std::size_t(k) * n], n, 2 * rmax);
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

std::string record_to_text(const Record& r, const std::string& summary_json) {
    using J = nlohmann::ordered_json;
    J j;
    j["format"] = "mobb crowd record";
    j["version"] = 1;
    j["graph"] = r.graph;
    j["dt"] = r.dt;
    j["frames"] = r.frames;
    j["world"] = {r.width, r.height};
    j["agents"] = r.tracks.size();
    j["seed"] = r.seed;
    j["tree"] = r.tree;
    j["select"] = r.select;
    j["summary"] = summary_json.empty() ? J::object() : J::parse(summary_json);
    J tracks = J::array();
    for (const AgentTrack& t : r.tracks) {
        J clips = J::array();
        for (const PlacedClip& c : t.clips)
            clips.push_back({{"clip", c.clip},
                             {"start", c.start},
                             {"place", {c.place.x, c.place.y, c.place.theta, c.place.t0}},
                             {"fallback", c.fallback},
                             {"commit", c.commit}});
        J samples = J::array();
        for (const auto& s : t.samples) samples.push_back({s[0], s[1], s[2], s[3]});
        tracks.push_back({{"clips", clips}, {"samples", samples}});
    }
    j["tracks"] = tracks;
    J choices = J::array();
    for (const ChoicePoint& c : r.choices) {
        J cands = J::array();
        for (const Candidate& k : c.candidates) {
            J against = J::array();
            for (const CandidateQuery& q : k.against) against.push_back({q.agent, q.index, int(q.hit)});
            cands.push_back({{"clip", k.clip},
                             {"outside", k.outside},
                             {"queries", k.queries},
                             {"hits", k.hits},
                             {"against", against}});
        }
        choices.push_back({{"agent", c.agent},
                           {"frame", c.frame},
                           {"t", util::rounded(double(c.frame) * r.dt, 9)},
                           {"taken", c.taken},
                           {"fallback", c.fallback},
                           {"queries", c.queries},
                           {"tests2d", c.tests2d},
                           {"tests3d", c.tests3d},
                           {"samples", c.samples},
                           {"pruned", c.pruned},
                           {"candidates", cands}});
    }
    j["choices"] = choices;
    return util::readable_json(j);
}

Record load_record(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file + ": cannot open");
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw std::runtime_error(file + ": not valid JSON");
    try {
        Record r;
        r.graph = j.at("graph").get<std::string>();
        r.dt = j.at("dt").get<double>();
        r.frames = j.at("frames").get<std::int64_t>();
        r.width = j.at("world").at(0).get<double>();
        r.height = j.at("world").at(1).get<double>();
        r.seed = j.at("seed").get<std::uint64_t>();
        r.tree = j.at("tree").get<std::string>();
        r.select = j.at("select").get<std::string>();
        for (const auto& t : j.at("tracks")) {
            AgentTrack track;
            for (const auto& c : t.at("clips")) {
                const auto& p = c.at("place");
                track.clips.push_back(
                    {c.at("clip").get<int>(),
                     c.at("start").get<std::int64_t>(),
                     {p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>(), p.at(3).get<double>()},
                     c.at("fallback").get<bool>(),
                     c.at("commit").get<std::int64_t>()});
            }
            for (const auto& s : t.at("samples"))
                track.samples.push_back(
                    {s.at(0).get<double>(), s.at(1).get<double>(), s.at(2).get<double>(), s.at(3).get<double>()});
            if (std::int64_t(track.samples.size()) != r.frames)
                throw std::runtime_error("a track has " + std::to_string(track.samples.size()) + " samples, expected " +
                                         std::to_string(r.frames));
            r.tracks.push_back(std::move(track));
        }
        for (const auto& c : j.at("choices")) {
            ChoicePoint cp;
            cp.agent = c.at("agent").get<int>();
            cp.frame = c.at("frame").get<std::int64_t>();
            cp.taken = c.at("taken").get<int>();
            cp.fallback = c.at("fallback").get<bool>();
            cp.queries = c.at("queries").get<std::uint64_t>();
            cp.tests2d = c.at("tests2d").get<std::uint64_t>();
            cp.tests3d = c.at("tests3d").get<std::uint64_t>();
            cp.samples = c.at("samples").get<std::uint64_t>();
            cp.pruned = c.at("pruned").get<std::uint64_t>();
            for (const auto& k : c.at("candidates")) {
                Candidate cand{k.at("clip").get<int>(),
                               k.at("outside").get<bool>(),
                               k.at("queries").get<int>(),
                               k.at("hits").get<int>(),
                               {}};
                for (const auto& q : k.at("against")) {
                    const CandidateQuery cq{q.at(0).get<int>(), q.at(1).get<int>(), q.at(2).get<int>() != 0};
                    if (cq.agent < 0 || std::size_t(cq.agent) >= r.tracks.size() || cq.index < 0 ||
                        std::size_t(cq.index) >= r.tracks[std::size_t(cq.agent)].clips.size())
                        throw std::runtime_error("choice " + std::to_string(r.choices.size()) +
                                                 ": a query names a clip not in the tracks");
                    cand.against.push_back(cq);
                }
                cp.candidates.push_back(std::move(cand));
            }
            r.choices.push_back(std::move(cp));
        }
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

}  // namespace mobb::crowd
