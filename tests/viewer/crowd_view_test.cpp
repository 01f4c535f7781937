// The crowd view without images: every query a candidate lists opens with the recorded answer, the
// skeletons stand on their agents' disks, sources load once, and unreadable inputs leave the disks
// with a reason instead of a crash.
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "crowd_view.h"
#include "render_test_util.h"
#include "state.h"

namespace mobb::test {
namespace {

using viewer::State;

/// A copy of `from` (JSON) with `edit` applied, written to the test output folder as `name`.
std::string edited_copy(const std::string& from, const std::string& name,
                        const std::function<void(nlohmann::json&)>& edit) {
    std::ifstream in(from);
    nlohmann::json j = nlohmann::json::parse(in);
    edit(j);
    const std::string out = std::string(MOBB_TEST_OUT) + "/" + name;
    std::ofstream(out) << j.dump();
    return out;
}

// Queries of the candidate clip against another agent's clip open; the others (held ground, walls,
// the candidate's escape clips) are refused with the reason.
TEST(CrowdTrace, EveryListedQueryOpensWithTheRecordedAnswer) {
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    State s = viewer::load_crowd_state(record, 1.5f);
    ASSERT_TRUE(s.crowd->graph) << s.crowd->graph_error;
    const crowd::Record r = crowd::load_record(record);  // the whole record, read on its own
    ASSERT_EQ(s.crowd->reader->choice_count(), r.choices.size());
    int opened = 0, hits = 0, refused = 0;
    for (std::size_t k = 0; k < r.choices.size(); ++k) {
        const crowd::ChoicePoint& c = r.choices[k];
        viewer::select_choice(s, -1, int(k));
        ASSERT_EQ(s.crowd->candidate_clips.size(), c.candidates.size());
        for (std::size_t i = 0; i < c.candidates.size(); ++i) {
            const crowd::Candidate& cand = c.candidates[i];
            EXPECT_EQ(int(cand.against.size()), cand.queries) << "choice " << k << " candidate " << i;
            for (std::size_t j = 0; j < cand.against.size(); ++j) {
                const crowd::CandidateQuery& q = cand.against[j];
                std::string message;
                const bool traceable = q.mine == 0 && q.agent >= 0 && q.piece >= 0;
                ASSERT_EQ(viewer::open_candidate_query(s, int(i), int(j), &message), traceable) << message;
                if (!traceable) {
                    EXPECT_NE(message.find("not a clip to trace"), std::string::npos) << message;
                    ++refused;
                    continue;
                }
                ASSERT_TRUE(s.queried);
                EXPECT_FALSE(s.trace.empty());
                EXPECT_EQ(s.answer, q.hit) << "choice " << k << " candidate " << i << " query " << j << ": " << message;
                EXPECT_EQ(s.scene.step, 0);
                EXPECT_EQ(s.crowd->opened_candidate, int(i));
                EXPECT_EQ(s.crowd->opened_query, int(j));
                // The query's other clip is where the record placed it.
                const crowd::FramedClip other = *crowd::query_clip(r, q);
                EXPECT_EQ(viewer::query_clip(*s.crowd, q)->frame, other.frame);
                EXPECT_EQ(s.places[std::size_t(s.scene.query_b)].x, other.place.x);
                EXPECT_EQ(s.places[std::size_t(s.scene.query_b)].t0, other.place.t0);
                // Opening another query replaces the other clip instead of piling them up.
                EXPECT_EQ(s.clips.size(), std::size_t(s.crowd->agents) + c.candidates.size() + 1);
                ++opened;
                hits += s.answer ? 1 : 0;
            }
        }
    }
    EXPECT_GT(opened, 20);
    EXPECT_GT(hits, 0);
    EXPECT_LT(hits, opened);
    EXPECT_GT(refused, 0);
    viewer::select_choice(s, 0, -1);
    EXPECT_EQ(s.clips.size(), r.tracks.size());
    EXPECT_EQ(s.scene.query_a, -1);
    EXPECT_EQ(s.crowd->opened_query, -1);
}

TEST(CrowdTrace, BadQueryIndicesAreRefused) {
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty());
    State s = viewer::load_crowd_state(record, 1.5f);
    std::string message;
    EXPECT_FALSE(viewer::open_candidate_query(s, 0, 0, &message));
    EXPECT_EQ(message, "no choice point selected");
    viewer::select_choice(s, -1, 0);
    const auto& c = s.crowd->selected;
    EXPECT_FALSE(viewer::open_candidate_query(s, int(c.candidates.size()), 0, &message));
    EXPECT_FALSE(viewer::open_candidate_query(s, 0, int(c.candidates[0].against.size()), &message));
    EXPECT_FALSE(viewer::open_candidate_query(s, 0, -1, &message));
    EXPECT_NE(message.find("has no query"), std::string::npos) << message;
    EXPECT_FALSE(s.queried);
}

/// At every frame (sampled), each agent's skeleton root lies on its recorded disk's centre: the pose
/// went through the graph's localisation and the clip's placement like the path did.
// Planted feet are marked (issue 47): each mark is a small square on the ground at the cursor, centred on
// an ankle or toe of a skeleton drawn then, under that agent's disk; walking agents plant a foot most of
// the time, so marks are many.
TEST(CrowdSkeletons, PlantedFeetAreMarkedUnderThem) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty());
    State s = viewer::load_crowd_state(record, 1.5f);
    const crowd::Record r = crowd::load_record(record);
    std::size_t marks = 0, feet = 0;
    for (std::int64_t k = 0; k < r.frames; k += 7) {
        const double t = (double(k) + 0.5) * r.dt;
        std::vector<render::Prism> planted;
        const auto skeletons = viewer::agent_skeletons(*s.crowd, t, s.colors, &planted);
        ASSERT_EQ(skeletons.size(), r.tracks.size()) << viewer::skeleton_problem(*s.crowd);
        feet += 2 * skeletons.size();
        marks += planted.size();
        for (const render::Prism& m : planted) {
            ASSERT_EQ(m.ground.size(), 4u);
            EXPECT_TRUE(m.on_top && m.t0 == t && m.t1 == t);
            const double x = 0.5 * (m.ground[0][0] + m.ground[2][0]), y = 0.5 * (m.ground[0][1] + m.ground[2][1]);
            bool on_a_foot = false;
            for (std::size_t a = 0; a < skeletons.size() && !on_a_foot; ++a) {
                const auto& disk = r.tracks[a].samples[std::size_t(k)];
                if (std::hypot(x - disk[1], y - disk[2]) > disk[3] + 1e-6) continue;
                for (const glm::dvec3& j : skeletons[a].joints)
                    on_a_foot = on_a_foot || (std::abs(j.x - x) < 1e-9 && std::abs(j.y - y) < 1e-9 && j.z < 0.2);
            }
            EXPECT_TRUE(on_a_foot) << "a mark at (" << x << ", " << y << ") at frame " << k;
        }
    }
    EXPECT_GT(marks, feet / 4) << "planted feet marked";
    EXPECT_LT(marks, feet);
}

TEST(CrowdSkeletons, RootsStandOnTheirDisks) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty());
    State s = viewer::load_crowd_state(record, 1.5f);
    ASSERT_TRUE(s.crowd->graph) << s.crowd->graph_error;
    const crowd::Record r = crowd::load_record(record);
    int checked = 0;
    for (std::int64_t k = 0; k < r.frames; k += 5) {
        const double t = (double(k) + 0.5) * r.dt;
        const auto skeletons = viewer::agent_skeletons(*s.crowd, t, s.colors);
        ASSERT_EQ(skeletons.size(), r.tracks.size()) << viewer::skeleton_problem(*s.crowd);
        for (std::size_t a = 0; a < skeletons.size(); ++a) {
            const render::PosedSkeleton& p = skeletons[a];
            ASSERT_FALSE(p.joints.empty());
            const glm::dvec3 g = p.joints[0];
            const auto& disk = r.tracks[a].samples[std::size_t(k)];
            // The graph rounds clip paths to micrometres; the record chains placements in doubles.
            EXPECT_NEAR(g.x, disk[1], 1e-4) << "agent " << a << " frame " << k;
            EXPECT_NEAR(g.y, disk[2], 1e-4) << "agent " << a << " frame " << k;
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);
    EXPECT_EQ(viewer::skeleton_problem(*s.crowd), "");
}

TEST(CrowdSkeletons, SourcesLoadOnce) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty());
    State s = viewer::load_crowd_state(record, 1.5f);
    ASSERT_TRUE(s.crowd->poses);
    // Posing the agents at t = 0 loads every source, once (the poses carry the joints all sources share,
    // and blend across them at clip starts).
    viewer::agent_skeletons(*s.crowd, 0.0, s.colors);
    EXPECT_EQ(s.crowd->poses->loaded(), int(s.crowd->graph->sources.size()));
    ASSERT_TRUE(s.crowd->poser);
    // Posing again loads nothing more and keeps the same poser.
    const auto* poser = s.crowd->poser.get();
    const auto first = viewer::agent_skeletons(*s.crowd, 1.0, s.colors);
    const auto again = viewer::agent_skeletons(*s.crowd, 1.0, s.colors);
    EXPECT_EQ(s.crowd->poser.get(), poser);
    ASSERT_EQ(first.size(), again.size());
    for (std::size_t a = 0; a < first.size(); ++a) EXPECT_EQ(first[a].joints, again[a].joints);
    // The layer off: frame_of poses nobody.
    s.scene.layers.skeletons = false;
    EXPECT_TRUE(viewer::frame_of(s).posed.empty());
    s.scene.layers.skeletons = true;
    EXPECT_EQ(viewer::frame_of(s).posed.size(), s.crowd->record().tracks.size());
}

TEST(CrowdSkeletons, UnreadableGraphKeepsTheDisks) {
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty());
    const std::string bad =
        edited_copy(record, "crowd_no_graph.json", [](nlohmann::json& j) { j["graph"] = "/no/such/graph.json"; });
    State s = viewer::load_crowd_state(bad, 1.5f);
    EXPECT_FALSE(s.crowd->graph);
    EXPECT_EQ(s.clips.size(), s.crowd->record().tracks.size());
    EXPECT_NE(viewer::skeleton_problem(*s.crowd).find("/no/such/graph.json"), std::string::npos);
    EXPECT_TRUE(viewer::frame_of(s).posed.empty());
    viewer::select_choice(s, -1, 0);
    std::string message;
    EXPECT_FALSE(viewer::open_candidate_query(s, 0, 0, &message));
    EXPECT_NE(message.find("graph"), std::string::npos) << message;
}

TEST(CrowdSkeletons, MissingSourceNamesTheFile) {
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty());
    // The committed graph with every source renamed: paths still fine, mocap missing.
    const std::string graph = edited_copy(MOBB_GRAPH, "crowd_graph_no_sources.json", [](nlohmann::json& j) {
        for (auto& src : j["sources"]) src["file"] = "cmu/no_such_take.bvh";
    });
    const std::string rec =
        edited_copy(record, "crowd_missing_sources.json", [&](nlohmann::json& j) { j["graph"] = graph; });
    State s = viewer::load_crowd_state(rec, 1.5f);
    ASSERT_TRUE(s.crowd->graph) << s.crowd->graph_error;
    EXPECT_TRUE(viewer::frame_of(s).posed.empty());
    const std::string problem = viewer::skeleton_problem(*s.crowd);
    EXPECT_NE(problem.find("no_such_take.bvh"), std::string::npos) << problem;
    EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
    EXPECT_EQ(s.clips.size(), s.crowd->record().tracks.size());
}

// A scenario record draws its walls, its obstacles (filled) and a post per goal; contacts at the cursor
// ring both disks on top; the timeline lists fallbacks and contact frames and jumps to them.
TEST(CrowdOverlay, WallsObstaclesGoalsAndContacts) {
    const std::string record = scenario_record("doorway_two_way");
    ASSERT_FALSE(record.empty());
    State s = viewer::load_crowd_state(record, 1.5f);
    const crowd::Record& r = s.crowd->record();
    const crowd::Record whole = crowd::load_record(record);
    const double end = double(r.frames) * r.dt;
    auto prisms = viewer::crowd_prisms(*s.crowd, 1.0);
    ASSERT_EQ(prisms.size(), 1 + r.world.obstacles.size() + 2);  // walls, the door's two posts, two goals
    EXPECT_EQ(prisms[0].ground.size(), 4u);
    EXPECT_EQ(prisms[0].ground[2][0], r.world.x1);
    EXPECT_EQ(prisms[1].ground, r.world.obstacles[0].vertices);
    EXPECT_GT(prisms[1].fill, 0.0f);
    for (const auto& p : prisms) {
        EXPECT_EQ(p.t0, 0.0);
        EXPECT_EQ(p.t1, end);
        EXPECT_FALSE(p.on_top);
    }
    EXPECT_NEAR(prisms[3].ground[0][0], r.tracks[0].goals[0][0] + 0.15, 1e-12);
    EXPECT_TRUE(s.crowd->marks.empty()) << "a passed scenario: no fallback, no contact";
    // Two contacts: agent 1 put onto agent 0 at frames 40 and 41 (of the window: all frames).
    crowd::SampleWindow& w = s.crowd->window;
    ASSERT_TRUE(s.crowd->whole());
    for (std::size_t f : {40u, 41u}) {
        w.samples[f * w.width() + 1][1] = w.samples[f * w.width()][1];
        w.samples[f * w.width() + 1][2] = w.samples[f * w.width()][2];
    }
    s.crowd->fallbacks.push_back({5, whole.choices[5].agent, whole.choices[5].frame});
    viewer::mark_contacts(*s.crowd);
    prisms = viewer::crowd_prisms(*s.crowd, 40.5 * r.dt);
    ASSERT_EQ(prisms.size(), 1 + r.world.obstacles.size() + 2 + 2);
    EXPECT_TRUE(prisms.back().on_top);
    EXPECT_EQ(prisms.back().t0, 40.5 * r.dt);
    EXPECT_EQ(viewer::crowd_prisms(*s.crowd, 42.5 * r.dt).size(), 1 + r.world.obstacles.size() + 2);
    const auto& marks = s.crowd->marks;
    ASSERT_EQ(marks.size(), 3u);
    int contacts = 0, fallbacks = 0;
    for (std::size_t k = 0; k < marks.size(); ++k) {
        if (k) {
            EXPECT_LE(marks[k - 1].frame, marks[k].frame);
        }
        (marks[k].kind == viewer::TimelineMark::Contact ? contacts : fallbacks) += 1;
    }
    EXPECT_EQ(contacts, 2);
    EXPECT_EQ(fallbacks, 1);
    // Jumping: to the nearest mark within reach, the cursor inside its frame.
    const viewer::TimelineMark* near = viewer::nearest_mark(marks, 44, 5);
    ASSERT_TRUE(near);
    EXPECT_EQ(near->frame, 41);
    EXPECT_EQ(viewer::nearest_mark(marks, 60, 5), nullptr);
    viewer::jump_to(s, *near);
    EXPECT_EQ(std::int64_t(s.scene.cursor / r.dt), 41);
    EXPECT_EQ(s.crowd->agent, 0);
    const viewer::TimelineMark* fallback = viewer::nearest_mark(marks, whole.choices[5].frame, 0);
    ASSERT_TRUE(fallback);
    viewer::jump_to(s, *fallback);
    EXPECT_EQ(s.crowd->choice, 5);
    EXPECT_EQ(s.crowd->agent, whole.choices[5].agent);
}

/// A 60-agent, 30 s crowd streamed to HDF5 by the real `mobb crowd`: 900 frames in blocks of 256, right
/// of way and escapes among its choice points. Written once per test process.
std::string long_record() {
    struct Made {
        std::string path;
        ~Made() {
            if (!path.empty()) std::remove(path.c_str());
        }
    };
    static const Made made = [] {
        // With its candidates (an HDF5 record keeps none unless asked): their queries open.
        const std::string out = std::string(MOBB_TEST_OUT) + "/crowd_long_" + std::to_string(getpid()) + ".h5";
        const std::string cmd = std::string("\"") + MOBB_EXE + "\" crowd --quiet --graph \"" + MOBB_GRAPH +
                                "\" --agents 60 --world 13x15 --seconds 30 --seed 2 --record-candidates --record \"" +
                                out + "\" > /dev/null";
        return Made{std::system(cmd.c_str()) == 0 ? out : std::string()};
    }();
    return made.path;
}

// A record larger than the viewer reads at once opens with the frames around the cursor alone: the
// header, clips and one block of samples read, the agents' stacks those frames of the record read
// whole; moving the cursor out of them reads those around it (from the cache when read before); the
// choice points listed are the agent's of those frames, and one selected opens its queries as recorded.
TEST(CrowdWindow, ALargeRecordOpensReadingTheFramesAroundTheCursor) {
    const std::string file = long_record();
    ASSERT_FALSE(file.empty()) << "mobb crowd --record failed";
    const crowd::RecordFile whole = crowd::read_record_file(file);
    const crowd::Record& r = whole.record;
    ASSERT_EQ(r.frames, 900);
    // At most 200 frames of the 60 agents at once; the cursor at 15 s, 1 s drawn either side.
    State s = viewer::load_crowd_state(file, 1.5f, 15.0, 1.0, 60 * 200);
    viewer::CrowdView& v = *s.crowd;
    ASSERT_TRUE(v.reader->lazy());
    EXPECT_FALSE(v.whole());
    // Frames of 15 s -/+ 1 s drawn -/+ 1 s read ahead (390 to 510): block 1, frames 256 to 511, read alone.
    EXPECT_EQ(v.window.first, 390);
    EXPECT_EQ(v.window.last, 511);
    EXPECT_EQ(v.reader->counts().frames, 256);
    EXPECT_EQ(v.reader->counts().choices, 0);
    EXPECT_FALSE(viewer::crowd_extent(v).empty);  // framed as the whole run
    const auto check_stacks = [&] {
        for (std::size_t a = 0; a < r.tracks.size(); ++a) {
            const Path& path = s.clips[a].tree->path();
            ASSERT_EQ(std::int64_t(path.size()), v.window.last - v.window.first) << "agent " << a;
            EXPECT_EQ(s.places[a].t0, r.tracks[a].samples[std::size_t(v.window.first)][0]);
            for (std::size_t k = 0; k < path.size(); ++k) {
                const auto& d = r.tracks[a].samples[std::size_t(v.window.first) + k];
                ASSERT_TRUE(path.samples[k].x == d[1] && path.samples[k].y == d[2] && path.samples[k].r == d[3])
                    << "agent " << a << " frame " << v.window.first + std::int64_t(k);
            }
        }
    };
    check_stacks();
    // Still within the frames at hand: nothing read. Out of them: the frames around the cursor.
    s.scene.cursor = 15.5;
    EXPECT_FALSE(viewer::sync_crowd(s));
    s.scene.cursor = 25.0;
    EXPECT_TRUE(viewer::sync_crowd(s));
    EXPECT_TRUE(v.window.first <= 24 * 30 && v.window.last >= 26 * 30 + 1);
    EXPECT_EQ(v.reader->counts().frames, 256 + 256 + (900 - 768));  // blocks 2 and 3
    check_stacks();
    s.scene.cursor = 15.0;
    EXPECT_TRUE(viewer::sync_crowd(s));
    EXPECT_EQ(v.reader->counts().frames, 256 + 256 + (900 - 768));  // block 1 again, from the cache
    EXPECT_GT(v.reader->counts().cached, 0);
    // Agent 3's choice points at those frames, as the whole record has them.
    const auto& listed = viewer::agent_choices(v, 3);
    std::vector<std::size_t> rows;
    for (std::size_t k = 0; k < r.choices.size(); ++k)
        if (r.choices[k].agent == 3 && r.choices[k].frame >= v.window.first && r.choices[k].frame < v.window.last)
            rows.push_back(k);
    ASSERT_EQ(listed.size(), rows.size());
    ASSERT_FALSE(rows.empty());
    for (std::size_t k = 0; k < rows.size(); ++k) EXPECT_EQ(listed[k].row, rows[k]);
    // Every query of their candidates opens as the crowd answered it.
    ASSERT_TRUE(v.graph) << v.graph_error;
    int opened = 0;
    for (const std::size_t row : rows) {
        viewer::select_choice(s, -1, int(row));
        ASSERT_EQ(v.selected.candidates.size(), r.choices[row].candidates.size());
        for (std::size_t i = 0; i < v.selected.candidates.size(); ++i)
            for (std::size_t j = 0; j < v.selected.candidates[i].against.size(); ++j) {
                const crowd::CandidateQuery& q = v.selected.candidates[i].against[j];
                std::string message;
                if (!viewer::open_candidate_query(s, int(i), int(j), &message)) continue;
                EXPECT_EQ(s.answer, q.hit) << message;
                EXPECT_EQ(viewer::query_clip(v, q)->place.t0, crowd::query_clip(r, q)->place.t0);
                ++opened;
            }
    }
    EXPECT_GT(opened, 0);
    // Each read once, with the choice points whose escape clips its queries met.
    std::int64_t named = 0;
    for (const std::size_t row : rows) {
        std::set<int> met;
        for (const auto& cand : r.choices[row].candidates)
            for (const auto& q : cand.against)
                if (q.agent >= 0 && q.piece > 0) met.insert(q.choice);
        named += std::int64_t(met.size());
    }
    EXPECT_EQ(v.reader->counts().choices, std::int64_t(rows.size()) + named);
}

// The skeletons at the cursor of a record read in windows are those of the record read whole (their
// bound looks at the disks ahead, which the window holds).
TEST(CrowdWindow, SkeletonsAreThoseOfTheWholeRecord) {
    MOBB_NEEDS_MOCAP();
    const std::string file = long_record();
    ASSERT_FALSE(file.empty()) << "mobb crowd --record failed";
    State part = viewer::load_crowd_state(file, 1.5f, 15.0, 1.0, 60 * 200);
    State all = viewer::load_crowd_state(file, 1.5f, 15.0, 1.0);
    ASSERT_FALSE(part.crowd->whole());
    ASSERT_TRUE(all.crowd->whole());
    for (const double t : {14.01, 15.0, 16.49}) {
        const auto a = viewer::agent_skeletons(*part.crowd, t, part.colors);
        const auto b = viewer::agent_skeletons(*all.crowd, t, all.colors);
        ASSERT_EQ(a.size(), b.size()) << viewer::skeleton_problem(*part.crowd);
        ASSERT_EQ(a.size(), 60u);
        for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k].joints, b[k].joints) << "agent " << k << " at " << t;
    }
}

}  // namespace
}  // namespace mobb::test
