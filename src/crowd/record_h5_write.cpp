// Writing a crowd record as HDF5 (the layout in docs/formats.md): the header as attributes of the root,
// the samples by frame blocks, and one group of columns per table, rows in the record's order and tables
// nested by their owner's row (a candidate's "choice", a query's "candidate").
#include <algorithm>
#include <cmath>
#include <limits>

#include "h5.h"
#include "record_json.h"

namespace mobb::crowd {

namespace {

using I = std::vector<std::int64_t>;
using D = std::vector<double>;
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
const h5::Layout kColumn{};
const h5::Layout kPair{{2}}, kTriple{{3}}, kPlace{{4}};

// Frames per block of samples: about 64 k disks (2 MB) a block, 1 to 256 frames.
hsize_t block_frames(std::size_t agents) { return hsize_t(std::clamp<std::size_t>(65536 / std::max<std::size_t>(1, agents), 1, 256)); }

void write_header(hid_t f, const Record& r, const std::string& summary, const std::string& metrics) {
    h5::write_text(f, "format", "mobb crowd record");
    h5::write_numbers<std::int64_t>(f, "version", {2});
    h5::write_text(f, "graph", r.graph);
    h5::write_numbers<double>(f, "dt", {r.dt});
    h5::write_numbers<std::int64_t>(f, "frames", {r.frames});
    h5::write_numbers<std::int64_t>(f, "agents", {std::int64_t(r.tracks.size())});
    h5::write_numbers<std::uint64_t>(f, "seed", {r.seed});
    h5::write_text(f, "tree", r.tree);
    h5::write_text(f, "select", r.select);
    if (!r.scenario.empty()) h5::write_text(f, "scenario", r.scenario);
    h5::write_numbers<double>(f, "world", {r.world.x0, r.world.y0, r.world.x1, r.world.y1});
    h5::write_numbers<std::int64_t>(f, "walls", {r.world.walls});
    h5::write_text(f, "summary", summary.empty() ? "{}" : summary);
    if (!metrics.empty()) h5::write_text(f, "metrics", metrics);
}

void write_obstacles(hid_t f, const World& w) {
    I polygon;
    D vertex;
    for (std::size_t k = 0; k < w.obstacles.size(); ++k)
        for (const auto& v : w.obstacles[k].vertices) polygon.push_back(std::int64_t(k)), vertex.insert(vertex.end(), {v[0], v[1]});
    h5::write_rows(f, "/obstacles/polygon", polygon, kColumn);
    h5::write_rows(f, "/obstacles/vertex", vertex, kPair);
}

void write_tracks(hid_t f, const Record& r) {
    I left, at_goal, goal_agent, agent, clip, start, fallback, commit;
    D goal, place;
    for (std::size_t a = 0; a < r.tracks.size(); ++a) {
        const AgentTrack& t = r.tracks[a];
        left.push_back(t.left_frame.value_or(-1));
        at_goal.push_back(t.at_goal == AtGoal::Leave);
        for (const auto& g : t.goals) goal_agent.push_back(std::int64_t(a)), goal.insert(goal.end(), {g[0], g[1]});
        for (const PlacedClip& c : t.clips) {
            agent.push_back(std::int64_t(a)), clip.push_back(c.clip), start.push_back(c.start);
            fallback.push_back(c.fallback), commit.push_back(c.commit);
            place.insert(place.end(), {c.place.x, c.place.y, c.place.theta, c.place.t0});
        }
    }
    h5::write_rows(f, "/tracks/left_frame", left, kColumn);
    h5::write_rows(f, "/tracks/at_goal", at_goal, kColumn);
    h5::write_rows(f, "/goals/agent", goal_agent, kColumn);
    h5::write_rows(f, "/goals/xy", goal, kPair);
    for (const auto& [name, column] : {std::pair{"agent", &agent}, {"clip", &clip}, {"start", &start},
                                       {"fallback", &fallback}, {"commit", &commit}})
        h5::write_rows(f, std::string("/clips/") + name, *column, kColumn);
    h5::write_rows(f, "/clips/place", place, kPlace);
}

// [frames, agents, 4]: agent a's disk [t, x, y, r] at frame k, NaN once it left.
void write_samples(hid_t f, const Record& r) {
    const std::size_t n = r.tracks.size();
    const h5::Layout layout{{hsize_t(n), 4}, block_frames(n), false};
    h5::write_rows<double>(f, "/tracks/samples", hsize_t(r.frames), layout, [&](hsize_t first, hsize_t count, double* out) {
        for (hsize_t k = first; k < first + count; ++k)
            for (std::size_t a = 0; a < n; ++a, out += 4) {
                const auto& s = r.tracks[a].samples;
                if (k < s.size()) std::copy(s[k].begin(), s[k].end(), out);
                else std::fill(out, out + 4, kNone);
            }
    });
}

// Clips placed from a frame on (a plan's escape, its intended clips, a reroute's escape), by owner row.
struct FramedTable {
    I owner, clip, frame;
    D place;
    void add(std::size_t row, const std::vector<FramedClip>& clips) {
        for (const FramedClip& c : clips) {
            owner.push_back(std::int64_t(row)), clip.push_back(c.clip), frame.push_back(c.frame);
            place.insert(place.end(), {c.place.x, c.place.y, c.place.theta});
        }
    }
    void write(hid_t f, const std::string& group, const char* owner_name) const {
        h5::write_rows(f, group + "/" + owner_name, owner, kColumn);
        h5::write_rows(f, group + "/clip", clip, kColumn);
        h5::write_rows(f, group + "/frame", frame, kColumn);
        h5::write_rows(f, group + "/place", place, kTriple);
    }
};

std::int64_t outcome_index(const std::string& outcome) {
    static const char* const kOutcomes[] = {"candidate", "escape", "arrived", "fallback", "right of way"};
    for (std::int64_t k = 0; k < 5; ++k)
        if (outcome == kOutcomes[k]) return k;
    return -1;
}

void write_choices(hid_t f, const Record& r) {
    I agent, frame, taken, outcome, fallback, queries, tests2d, tests3d, samples, pruned, hold_frame;
    D hold, reroute_hold;
    I reroute_choice, reroute_agent, reroute_frame;
    I cand_choice, cand_clip, outside, cand_queries, hits, crowded;
    I query_cand, q_agent, q_commit, q_piece, q_mine, q_hit;
    FramedTable escapes, intended, reroute_escapes;
    for (std::size_t c = 0; c < r.choices.size(); ++c) {
        const ChoicePoint& cp = r.choices[c];
        agent.push_back(cp.agent), frame.push_back(cp.frame), taken.push_back(cp.taken);
        outcome.push_back(outcome_index(cp.outcome)), fallback.push_back(cp.fallback);
        queries.push_back(std::int64_t(cp.queries)), tests2d.push_back(std::int64_t(cp.tests2d));
        tests3d.push_back(std::int64_t(cp.tests3d)), samples.push_back(std::int64_t(cp.samples));
        pruned.push_back(std::int64_t(cp.pruned));
        hold_frame.push_back(cp.holds ? cp.hold_frame : -1);
        hold.insert(hold.end(), {cp.holds ? cp.hold[0] : kNone, cp.holds ? cp.hold[1] : kNone, cp.holds ? cp.hold[2] : kNone});
        escapes.add(c, cp.escape);
        intended.add(c, cp.intended);
        for (const ReroutedPlan& p : cp.reroutes) {
            reroute_escapes.add(reroute_choice.size(), p.escape);
            reroute_choice.push_back(std::int64_t(c)), reroute_agent.push_back(p.agent), reroute_frame.push_back(p.hold_frame);
            reroute_hold.insert(reroute_hold.end(), p.hold.begin(), p.hold.end());
        }
        for (const Candidate& k : cp.candidates) {
            for (const CandidateQuery& q : k.against) {
                query_cand.push_back(std::int64_t(cand_choice.size())), q_agent.push_back(q.agent);
                q_commit.push_back(q.commit), q_piece.push_back(q.piece), q_mine.push_back(q.mine), q_hit.push_back(q.hit);
            }
            cand_choice.push_back(std::int64_t(c)), cand_clip.push_back(k.clip), outside.push_back(k.outside);
            cand_queries.push_back(k.queries), hits.push_back(k.hits), crowded.push_back(k.crowded);
        }
    }
    const auto columns = [&](const std::string& group, std::initializer_list<std::pair<const char*, const I*>> list) {
        for (const auto& [name, column] : list) h5::write_rows(f, group + "/" + name, *column, kColumn);
    };
    columns("/choices", {{"agent", &agent}, {"frame", &frame}, {"taken", &taken}, {"outcome", &outcome},
                         {"fallback", &fallback}, {"queries", &queries}, {"tests2d", &tests2d}, {"tests3d", &tests3d},
                         {"samples", &samples}, {"pruned", &pruned}, {"hold_frame", &hold_frame}});
    h5::write_rows(f, "/choices/hold", hold, kTriple);
    escapes.write(f, "/escapes", "choice");
    intended.write(f, "/intended", "choice");
    columns("/reroutes", {{"choice", &reroute_choice}, {"agent", &reroute_agent}, {"hold_frame", &reroute_frame}});
    h5::write_rows(f, "/reroutes/hold", reroute_hold, kTriple);
    reroute_escapes.write(f, "/reroute_escapes", "reroute");
    columns("/candidates", {{"choice", &cand_choice}, {"clip", &cand_clip}, {"outside", &outside},
                            {"queries", &cand_queries}, {"hits", &hits}, {"crowded", &crowded}});
    columns("/queries", {{"candidate", &query_cand}, {"agent", &q_agent}, {"commit", &q_commit},
                         {"piece", &q_piece}, {"mine", &q_mine}, {"hit", &q_hit}});
}

}  // namespace

void write_h5_record(const std::string& file, const Record& r, const std::string& summary_json,
                     const std::string& metrics_json) {
    h5::quiet();
    try {
        const h5::Id f(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
        if (!f.valid()) throw h5::Error("cannot create");
        write_header(f.get(), r, summary_json, metrics_json);
        h5::write_numbers<std::int64_t>(f.get(), "complete", {0});
        write_obstacles(f.get(), r.world);
        write_tracks(f.get(), r);
        write_choices(f.get(), r);
        write_samples(f.get(), r);
        // Last: a reader tells a finished file from one whose writing stopped (killed, disk full).
        const h5::Id done(H5Aopen(f.get(), "complete", H5P_DEFAULT), H5Aclose);
        const std::int64_t one = 1;
        if (H5Awrite(done.get(), H5T_NATIVE_INT64, &one) < 0 || H5Fflush(f.get(), H5F_SCOPE_GLOBAL) < 0)
            throw h5::Error("cannot write");
    } catch (const h5::Error& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
}

}  // namespace mobb::crowd
