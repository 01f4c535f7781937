// Malformed crowd records: every field of a real record broken in turn (zero or negative steps, frames
// and counts, non-finite samples, indices past the agents, frames, choice points or solids, tracks of the
// wrong length) is refused by load_record with one line naming the file and the field; clip ids past the
// graph by check_graph_clips.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "files.h"
#include "mobb/crowd/record/record.h"
#include "mobb/crowd/record/record_file.h"
#include "mobb/crowd/sim/crowd.h"

namespace mobb::crowd {
namespace {

using nlohmann::json;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

const MotionGraph& graph() {
    static const MotionGraph g = load_graph(kGraph);
    return g;
}

// A real record: 8 agents for 6 s in a walled room with an obstacle (queries against agents, their
// ground, the walls and the obstacle), in the clip choice `select`.
json room_record(Selection select) {
    CrowdOptions o;
    o.agents = 8;
    o.seconds = 6;
    o.seed = 9;
    o.select = select;
    o.world.x1 = 9;
    o.world.y1 = 11;
    o.world.obstacles.push_back(Polygon::rectangle(3, 4, 4, 6));
    const CrowdRun run = run_crowd(graph(), NarrowPhase::sweep(graph()), o);
    return json::parse(record_to_text(run.record, summary_json(run.summary)));
}

const json& recorded() {
    static const json j = room_record(Selection::Wander);
    return j;
}

// A choice point with a candidate that lists queries, and the index of such a query of each kind.
struct Where {
    std::size_t choice = 0, candidate = 0;
};
Where with_queries() {
    const json& j = recorded();
    for (std::size_t c = 0; c < j["choices"].size(); ++c)
        for (std::size_t k = 0; k < j["choices"][c]["candidates"].size(); ++k)
            if (!j["choices"][c]["candidates"][k]["against"].empty()) return {c, k};
    return {};
}

// The error load_record gives the recorded JSON after `edit`, written to a file ("" when it reads).
std::string error_after(const std::function<void(json&)>& edit, std::string* file_out = nullptr) {
    json j = recorded();
    edit(j);
    const std::string file = test::temp_file("record_edited.json");
    std::ofstream(file) << j.dump();
    if (file_out) *file_out = file;
    std::string e;
    try {
        load_record(file);
    } catch (const std::runtime_error& x) {
        e = x.what();
    }
    std::remove(file.c_str());
    return e;
}

struct Case {
    const char* name;
    std::function<void(json&)> edit;
    std::string place;  // the error starts "FILE: " + place + ": "
};

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

std::vector<Case> corpus() {
    const Where w = with_queries();
    const std::string cp = "choices[" + std::to_string(w.choice) + "]";
    const std::string cand = cp + ".candidates[" + std::to_string(w.candidate) + "]";
    const auto C = [w](json& j) -> json& { return j["choices"][w.choice]; };
    const auto K = [w](json& j) -> json& { return j["choices"][w.choice]["candidates"][w.candidate]; };
    // One case a line: clang-format 14 breaks up a short lambda that holds a braced list.
    // clang-format off
    return {
        // The header.
        {"dt zero", [](json& j) { j["dt"] = 0; }, "dt"},
        {"dt negative", [](json& j) { j["dt"] = -1.0 / 30; }, "dt"},
        {"dt NaN", [](json& j) { j["dt"] = kNaN; }, "dt"},
        {"dt text", [](json& j) { j["dt"] = "1/30"; }, "dt"},
        {"dt of no graph (long)", [](json& j) { j["dt"] = 5; }, "dt"},
        {"dt of no graph (short)", [](json& j) { j["dt"] = 1e-7; }, "dt"},
        {"frames zero", [](json& j) { j["frames"] = 0; }, "frames"},
        {"frames negative", [](json& j) { j["frames"] = -180; }, "frames"},
        {"frames fractional", [](json& j) { j["frames"] = 180.5; }, "frames"},
        {"agents not the tracks", [](json& j) { j["agents"] = 99; }, "agents"},
        {"seed negative", [](json& j) { j["seed"] = -1; }, "seed"},
        {"version", [](json& j) { j["version"] = 4; }, "version"},
        {"world empty", [](json& j) { j["world"] = {0, 10}; }, "world"},
        {"world reversed", [](json& j) { j["world"] = {5, 0, 1, 10}; }, "world"},
        {"world of three", [](json& j) { j["world"] = {1, 2, 3}; }, "world"},
        {"world infinite", [](json& j) { j["world"] = {0, 0, kInf, 10}; }, "world[2]"},
        {"world far", [](json& j) { j["world"] = {0, 0, 1e300, 10}; }, "world[2]"},
        {"walls text", [](json& j) { j["walls"] = "yes"; }, "walls"},
        {"obstacle of one vertex", [](json& j) { j["obstacles"][0] = {{1, 1}}; }, "obstacles[0]"},
        {"obstacle vertex NaN", [](json& j) { j["obstacles"][0][1][0] = kNaN; }, "obstacles[0][1][0]"},
        {"summary text", [](json& j) { j["summary"] = 3; }, "summary"},
        {"no tracks", [](json& j) { j["tracks"] = json::array(); }, "tracks"},
        // Tracks.
        {"goal text", [](json& j) { j["tracks"][0]["goal"] = {"a", 1}; }, "tracks[0].goal[0]"},
        {"no clips", [](json& j) { j["tracks"][1]["clips"] = json::array(); }, "tracks[1].clips"},
        {"clip negative", [](json& j) { j["tracks"][1]["clips"][0]["clip"] = -1; }, "tracks[1].clips[0].clip"},
        {"first clip late", [](json& j) { j["tracks"][1]["clips"][0]["start"] = 5; }, "tracks[1].clips[0].start"},
        {"clips out of order",
         [](json& j) { j["tracks"][1]["clips"][1]["start"] = j["tracks"][1]["clips"][0]["start"]; },
         "tracks[1].clips[1].start"},
        {"clip past the run",
         [](json& j) {
             auto& c = j["tracks"][1]["clips"][1];
             c["start"] = j["frames"];
             c["place"][3] = j["frames"].get<double>() * j["dt"].get<double>();
         },
         "tracks[1].clips[1].start"},
        {"place NaN", [](json& j) { j["tracks"][1]["clips"][0]["place"][2] = kNaN; }, "tracks[1].clips[0].place[2]"},
        {"place t0 off its start", [](json& j) { j["tracks"][1]["clips"][1]["place"][3] = 100.0; },
         "tracks[1].clips[1].place[3]"},
        {"fallback text", [](json& j) { j["tracks"][1]["clips"][0]["fallback"] = 0; }, "tracks[1].clips[0].fallback"},
        {"choice below -1", [](json& j) { j["tracks"][1]["clips"][0]["choice"] = -2; }, "tracks[1].clips[0].choice"},
        {"choice past the choice points", [](json& j) { j["tracks"][1]["clips"].back()["choice"] = 1000000; },
         "tracks[1].clips["},
        {"samples one short", [](json& j) { j["tracks"][2]["samples"].erase(0); }, "tracks[2].samples"},
        {"radius negative", [](json& j) { j["tracks"][2]["samples"][7][3] = -0.3; }, "tracks[2].samples[7][3]"},
        {"radius NaN", [](json& j) { j["tracks"][2]["samples"][7][3] = kNaN; }, "tracks[2].samples[7][3]"},
        {"x infinite", [](json& j) { j["tracks"][2]["samples"][7][1] = kInf; }, "tracks[2].samples[7][1]"},
        {"x far", [](json& j) { j["tracks"][2]["samples"][7][1] = 1e308; }, "tracks[2].samples[7][1]"},
        {"radius of a giant", [](json& j) { j["tracks"][2]["samples"][7][3] = 40.0; }, "tracks[2].samples[7][3]"},
        {"goal far", [](json& j) { j["tracks"][0]["goal"] = {1, -1e9}; }, "tracks[0].goal[1]"},
        {"y text", [](json& j) { j["tracks"][2]["samples"][7][2] = "2"; }, "tracks[2].samples[7][2]"},
        {"time off its frame", [](json& j) { j["tracks"][2]["samples"][7][0] = 99.0; }, "tracks[2].samples[7][0]"},
        {"sample of three", [](json& j) { j["tracks"][2]["samples"][7] = {0, 1, 2}; }, "tracks[2].samples[7]"},
        // Choice points.
        {"agent past the tracks", [C](json& j) { C(j)["agent"] = 8; }, cp + ".agent"},
        {"agent negative", [C](json& j) { C(j)["agent"] = -1; }, cp + ".agent"},
        {"frame past the run", [C](json& j) { C(j)["frame"] = j["frames"]; }, cp + ".frame"},
        {"t off its frame", [C](json& j) { C(j)["t"] = -4.0; }, cp + ".t"},
        {"taken negative", [C](json& j) { C(j)["taken"] = -3; }, cp + ".taken"},
        {"outcome unknown", [C](json& j) { C(j)["outcome"] = "teleport"; }, cp + ".outcome"},
        {"queries negative", [C](json& j) { C(j)["queries"] = -1; }, cp + ".queries"},
        {"tests2d fractional", [C](json& j) { C(j)["tests2d"] = 0.5; }, cp + ".tests2d"},
        {"pruned negative", [C](json& j) { C(j)["pruned"] = -7; }, cp + ".pruned"},
        {"hold radius negative", [C](json& j) { C(j)["plan"]["hold"] = {1, 1, -0.3, 10}; }, cp + ".plan.hold[2]"},
        {"hold frame negative", [C](json& j) { C(j)["plan"]["hold"] = {1, 1, 0.3, -10}; }, cp + ".plan.hold[3]"},
        {"hold far", [C](json& j) { C(j)["plan"]["hold"] = {1e12, 1, 0.3, 10}; }, cp + ".plan.hold[0]"},
        {"escape frame negative", [C](json& j) { C(j)["plan"]["escape"] = {{0, -3, 1, 1, 0}}; },
         cp + ".plan.escape[0][1]"},
        {"escape clip negative", [C](json& j) { C(j)["plan"]["escape"] = {{-1, 3, 1, 1, 0}}; },
         cp + ".plan.escape[0][0]"},
        {"escape NaN", [C](json& j) { C(j)["plan"]["escape"] = {{0, 3, kNaN, 1, 0}}; }, cp + ".plan.escape[0][2]"},
        {"reroute past the agents",
         [C](json& j) {
             C(j)["plan"]["reroutes"] = {{{"agent", 8}, {"escape", json::array()}, {"hold", {1, 1, 0.3, 0}}}};
         },
         cp + ".plan.reroutes[0].agent"},
        // Candidates and their queries.
        {"candidate clip negative", [K](json& j) { K(j)["clip"] = -1; }, cand + ".clip"},
        {"meets_solid a number", [K](json& j) { K(j)["meets_solid"] = 1; }, cand + ".meets_solid"},
        {"leaves_world missing", [K](json& j) { K(j).erase("leaves_world"); }, cand},
        {"hits over queries", [K](json& j) { K(j)["hits"] = K(j)["queries"].get<int>() + 1; }, cand + ".hits"},
        {"queries fewer than listed",
         [K](json& j) {
             K(j)["queries"] = 0;
             K(j)["hits"] = 0;
         },
         cand + ".against"},
        {"query agent past the tracks", [K](json& j) { K(j)["against"][0] = {8, 0, 0, 0, 0}; },
         cand + ".against[0][0]"},
        {"query of a later choice point", [K](json& j) { K(j)["against"][0] = {0, 1000000, 0, 0, 0}; },
         cand + ".against[0][1]"},
        {"query of no solid", [K](json& j) { K(j)["against"][0] = {-1, 5, 0, 0, 0}; }, cand + ".against[0][1]"},
        {"query hit 2", [K](json& j) { K(j)["against"][0] = {0, -1, -1, 0, 2}; }, cand + ".against[0][4]"},
        {"query mine below -1", [K](json& j) { K(j)["against"][0] = {0, -1, -1, -2, 0}; }, cand + ".against[0][3]"},
        {"query of four", [K](json& j) { K(j)["against"][0] = {0, -1, -1, 0}; }, cand + ".against[0]"},
    };
    // clang-format on
}

TEST(RecordErrors, RealRecordReads) {
    EXPECT_EQ(error_after([](json&) {}), "");
    const Where w = with_queries();
    ASSERT_FALSE(recorded()["choices"][w.choice]["candidates"][w.candidate]["against"].empty());
    // The solids a query may name: the obstacle (0) and the four walls (1..4).
    EXPECT_EQ(error_after([w](json& j) {
                  j["choices"][w.choice]["candidates"][w.candidate]["against"][0] = {-1, 4, 0, 0, 0};
              }),
              "");
}

TEST(RecordErrors, EveryBadFieldIsNamed) {
    for (const Case& c : corpus()) {
        SCOPED_TRACE(c.name);
        std::string file;
        const std::string e = error_after(c.edit, &file);
        ASSERT_FALSE(e.empty()) << "accepted";
        EXPECT_EQ(e.rfind(file + ": " + c.place, 0), 0u) << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
}

TEST(RecordErrors, ClipsPastTheGraphAreNamed) {
    const std::string file = test::temp_file("record_clips.json");
    std::ofstream(file) << recorded().dump();
    Record r = load_record(file);
    std::remove(file.c_str());
    EXPECT_NO_THROW(check_graph_clips(r, graph().clips.size()));
    const int past = int(graph().clips.size());
    const auto error = [&](Record x) {
        try {
            check_graph_clips(x, graph().clips.size());
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    Record x = r;
    x.tracks[3].clips[0].clip = past;
    EXPECT_EQ(error(x).rfind("tracks[3].clips[0].clip: clip " + std::to_string(past) + " is not in the graph", 0), 0u)
        << error(x);
    x = r;
    x.choices[2].taken = past;
    EXPECT_EQ(error(x).rfind("choices[2].taken: ", 0), 0u) << error(x);
    x = r;
    ASSERT_FALSE(x.choices[2].candidates.empty());
    x.choices[2].candidates[0].clip = past;
    EXPECT_EQ(error(x).rfind("choices[2].candidates[0].clip: ", 0), 0u) << error(x);
    x = r;
    x.choices[2].escape.push_back({past, 10, {}});
    EXPECT_EQ(error(x).rfind("choices[2].plan.escape[", 0), 0u) << error(x);
}

// The same room walked at random (the paper's timing mode): candidates that leave the world.
const json& recorded_random() {
    static const json j = room_record(Selection::Random);
    return j;
}

// A candidate's flags each say one thing: meets_solid that a query of it met a wall or an obstacle
// (agent -1; the random mode queries none), leaves_world only in random mode.
TEST(RecordFlags, EachSaysOneThing) {
    for (const json* j : {&recorded(), &recorded_random()}) {
        const bool random = (*j)["select"] == "random";
        int leaves = 0, meets = 0;
        for (const json& cp : (*j)["choices"])
            for (const json& k : cp["candidates"]) {
                bool solid_hit = false;
                for (const json& q : k["against"]) solid_hit = solid_hit || (q[0] == -1 && q[4] == 1);
                EXPECT_EQ(k["meets_solid"].get<bool>(), solid_hit) << k.dump();
                if (!random) {
                    EXPECT_FALSE(k["leaves_world"].get<bool>()) << k.dump();
                }
                leaves += k["leaves_world"].get<bool>();
                meets += k["meets_solid"].get<bool>();
            }
        if (random) {
            EXPECT_GT(leaves, 0) << "random walks leave a 9 x 11 m room";
            EXPECT_EQ(meets, 0) << "the paper's workload queries no walls or obstacles";
        } else {
            EXPECT_GT(meets, 0) << "the obstacle and the walls are met";
        }
    }
}

// A record of version 2, before the names of one meaning: its clips' "commit", its candidates' one flag
// "outside" (leaves_world in random mode, meets_solid otherwise) and its summary's
// "fallbacks_outside_world" (the fallbacks meeting a wall or an obstacle).
json as_version_2(json j) {
    j["version"] = 2;
    j["summary"]["fallbacks_outside_world"] = j["summary"]["fallbacks_meeting_solids"];
    j["summary"].erase("fallbacks_meeting_solids");
    for (json& t : j["tracks"])
        for (json& c : t["clips"]) {
            c["commit"] = c["choice"];
            c.erase("choice");
        }
    const bool random = j["select"] == "random";
    for (json& cp : j["choices"])
        for (json& k : cp["candidates"]) {
            k["outside"] = k[random ? "leaves_world" : "meets_solid"];
            k.erase("leaves_world");
            k.erase("meets_solid");
        }
    return j;
}

// Read back as this version: the record of the version 3 text, but what version 2 did not keep.
TEST(RecordVersions, Version2ReadsInTodaysNames) {
    for (const json* j : {&recorded(), &recorded_random()}) {
        json expected = *j;
        if ((*j)["select"] == "random")
            for (json& cp : expected["choices"])
                for (json& k : cp["candidates"]) k["meets_solid"] = false;
        const std::string want = test::temp_file("record_v3.json"), old = test::temp_file("record_v2.json");
        std::ofstream(want) << expected.dump();
        std::ofstream(old) << as_version_2(*j).dump();
        EXPECT_EQ(record_to_text(load_record(old), "{}"), record_to_text(load_record(want), "{}"));
        EXPECT_EQ(read_record_file(old).summary_json, read_record_file(want).summary_json);
        std::remove(want.c_str());
        std::remove(old.c_str());
    }
}

}  // namespace
}  // namespace mobb::crowd
