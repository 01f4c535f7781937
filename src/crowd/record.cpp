#include "mobb/crowd/record.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "json_text.h"

namespace mobb::crowd {

namespace {

struct Cell {
    std::int64_t ix, iy;
    int agent;
    bool operator<(const Cell& o) const { return ix != o.ix ? ix < o.ix : iy != o.iy ? iy < o.iy : agent < o.agent; }
};

// Whether agent a plays a fallback clip at frame f (clips are in time order).
bool fallback_at(const AgentTrack& t, std::int64_t f) {
    auto it = std::upper_bound(t.clips.begin(), t.clips.end(), f, [](std::int64_t x, const PlacedClip& c) { return x < c.start; });
    return it != t.clips.begin() && std::prev(it)->fallback;
}

}  // namespace

std::vector<Contact> frame_contacts(const Record& record) {
    double rmax = 0;
    for (const AgentTrack& t : record.tracks)
        for (const auto& s : t.samples) rmax = std::max(rmax, s[3]);
    const double cell = std::max(2.0 * rmax, 1e-3);
    std::vector<Contact> out;
    std::vector<Cell> cells;
    const int n = int(record.tracks.size());
    for (std::int64_t f = 0; f < record.frames; ++f) {
        cells.clear();
        for (int a = 0; a < n; ++a) {
            const auto& s = record.tracks[std::size_t(a)].samples[std::size_t(f)];
            cells.push_back({std::int64_t(std::floor(s[1] / cell)), std::int64_t(std::floor(s[2] / cell)), a});
        }
        std::sort(cells.begin(), cells.end());
        std::vector<Contact> here;
        for (int a = 0; a < n; ++a) {
            const auto& sa = record.tracks[std::size_t(a)].samples[std::size_t(f)];
            const std::int64_t ix = std::int64_t(std::floor(sa[1] / cell)), iy = std::int64_t(std::floor(sa[2] / cell));
            for (std::int64_t dx = -1; dx <= 1; ++dx)
                for (std::int64_t dy = -1; dy <= 1; ++dy) {
                    auto it = std::lower_bound(cells.begin(), cells.end(), Cell{ix + dx, iy + dy, -1});
                    for (; it != cells.end() && it->ix == ix + dx && it->iy == iy + dy; ++it) {
                        const int b = it->agent;
                        if (b <= a) continue;
                        const auto& sb = record.tracks[std::size_t(b)].samples[std::size_t(f)];
                        const double ddx = sa[1] - sb[1], ddy = sa[2] - sb[2], r = sa[3] + sb[3];
                        if (ddx * ddx + ddy * ddy < r * r) here.push_back({f, a, b, false});
                    }
                }
        }
        std::sort(here.begin(), here.end(), [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
        for (Contact& c : here) {
            c.excused = fallback_at(record.tracks[std::size_t(c.a)], f) || fallback_at(record.tracks[std::size_t(c.b)], f);
            out.push_back(c);
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
            clips.push_back({{"clip", c.clip}, {"start", c.start}, {"place", {c.place.x, c.place.y, c.place.theta, c.place.t0}},
                             {"fallback", c.fallback}, {"commit", c.commit}});
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
            cands.push_back({{"clip", k.clip}, {"outside", k.outside}, {"queries", k.queries}, {"hits", k.hits},
                             {"against", against}});
        }
        choices.push_back({{"agent", c.agent}, {"frame", c.frame}, {"t", rounded(double(c.frame) * r.dt, 9)},
                           {"taken", c.taken}, {"fallback", c.fallback}, {"queries", c.queries}, {"tests2d", c.tests2d},
                           {"tests3d", c.tests3d}, {"samples", c.samples}, {"pruned", c.pruned}, {"candidates", cands}});
    }
    j["choices"] = choices;
    return readable_json(j);
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
                track.clips.push_back({c.at("clip").get<int>(), c.at("start").get<std::int64_t>(),
                                       {p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>(), p.at(3).get<double>()},
                                       c.at("fallback").get<bool>(), c.at("commit").get<std::int64_t>()});
            }
            for (const auto& s : t.at("samples"))
                track.samples.push_back({s.at(0).get<double>(), s.at(1).get<double>(), s.at(2).get<double>(), s.at(3).get<double>()});
            if (std::int64_t(track.samples.size()) != r.frames)
                throw std::runtime_error("a track has " + std::to_string(track.samples.size()) + " samples, expected " + std::to_string(r.frames));
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
                Candidate cand{k.at("clip").get<int>(), k.at("outside").get<bool>(), k.at("queries").get<int>(),
                               k.at("hits").get<int>(), {}};
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
