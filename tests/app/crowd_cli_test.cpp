// The crowd and benchmark subcommands as a user meets them: tables, records, exit codes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "files.h"
#include "mobb/crowd/record/record.h"
#include "mobb/io/load.h"
#include "query_set.h"
#include "run.h"

namespace mobb {
namespace {

using test::Result;
using test::temp_file;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

Result run(const std::string& args) { return test::run_mobb(args); }

TEST(CrowdCli, BenchCommandsPrintTables) {
    const std::string json = temp_file("t1.json"), png = temp_file("t1.png");
    const Result r = run("bench table1 --quick --quiet --graph " + kGraph + " --json " + json + " --png " + png);
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* row : {"| MOBB 1 level |", "| frame stepping |", "| best scan |", "| FCL |", "| circle sweep |"})
        EXPECT_NE(r.out.find(row), std::string::npos) << row;
    std::ifstream j(json);
    EXPECT_EQ(nlohmann::json::parse(j)["rows"].size(), 11u);
    std::remove(json.c_str());
    std::remove(png.c_str());
    const Result r2 = run("bench table2 --synth --quick --quiet --motions 2 --synth-seconds 10 --graph " + kGraph);
    ASSERT_EQ(r2.code, 0) << r2.err;
    EXPECT_NE(r2.out.find("| Hybrid 1 |"), std::string::npos);
}

// synth42 / synth120 / scale: each subcommand runs (--quick) and its JSON rows carry method + us_per_query.
void expect_json_rows(const std::string& file, const std::string& workload) {
    std::ifstream f(file);
    const nlohmann::json j = nlohmann::json::parse(f);
    EXPECT_EQ(j["workload"], workload);
    EXPECT_FALSE(j["rows"].empty());
    for (const auto& row : j["rows"]) {
        EXPECT_TRUE(row["method"].is_string());
        EXPECT_TRUE(row.contains("us_per_query"));
    }
    EXPECT_FALSE(j["targets"].empty());
}

TEST(CrowdCli, PerformanceWorkloads) {
    const std::string json = temp_file("w.json"), set = temp_file("w.queries");
    for (const std::string w : {"synth42", "synth120"}) {
        const Result r = run("bench " + w + " --quick --quiet --motions 2 --tests 300 --slow-queries 20 --graph " +
                             kGraph + " --json " + json + " --save-queries " + set);
        ASSERT_EQ(r.code, 0) << w << ": " << r.err;
        EXPECT_NE(r.out.find("| circle sweep |"), std::string::npos);
        expect_json_rows(json, w);
        EXPECT_EQ(bench::load_query_set(set).queries.size(), 300u);
    }
    const Result r = run("bench scale --quick --quiet --graph " + kGraph + " --json " + json);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("| 40 |"), std::string::npos);
    expect_json_rows(json, "scale");
    std::remove(json.c_str());
    std::remove(set.c_str());
}

// `bench scale --threads` takes any list of thread counts: a table column per count, every size's
// block of lines (times, speed-up, serial share, peak memory), the same in the JSON; one count N is 1,N.
TEST(CrowdCli, ScaleThreadCounts) {
    const std::string json = temp_file("scale_threads.json");
    Result r = run("bench scale --quick --quiet --threads 1,2,3 --graph " + kGraph + " --json " + json);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("| agents x simulated s | 1 thread | 2 threads | 3 threads |\n|---|---:|---:|---:|\n"),
              std::string::npos)
        << r.out;
    for (const std::string size : {"10 x 5", "40 x 5"})
        EXPECT_NE(r.out.find("| " + size + ": simulation s | "), std::string::npos) << size;
    const std::size_t share = r.out.find("| serial share of the frame step | - | ");
    ASSERT_NE(share, std::string::npos) << r.out;
    const std::string line = r.out.substr(share, r.out.find('\n', share) - share);
    EXPECT_EQ(std::count(line.begin(), line.end(), '|'), 5) << line;  // a label and three counts
    EXPECT_NE(r.out.find("| speed-up over 1 thread | 1.00 | "), std::string::npos);
    EXPECT_NE(r.out.find("| peak MB | "), std::string::npos);
    const nlohmann::json j = nlohmann::json::parse(test::slurp(json));
    EXPECT_EQ(j["threads"], nlohmann::json({1, 2, 3}));
    ASSERT_EQ(j["rows"].size(), 2u);
    for (const auto& row : j["rows"]) {
        ASSERT_EQ(row["by_threads"].size(), 3u);
        EXPECT_TRUE(row["identical"].get<bool>());
        EXPECT_TRUE(row["by_threads"][0]["serial_share"].is_null());
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(row["by_threads"][k]["threads"], k + 1);
            EXPECT_EQ(row["by_threads"][k]["digest"], row["digest_1"]);
        }
    }
    r = run("bench scale --quick --quiet --threads 2 --graph " + kGraph + " --json " + json);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(test::slurp(json))["threads"], nlohmann::json({1, 2}));
    EXPECT_EQ(run("bench scale --quick --threads 1,x").code, 2);
    EXPECT_EQ(run("bench scale --quick --threads 1,-2").code, 2);
    std::remove(json.c_str());
}

TEST(CrowdCli, CrowdPrintsSummaryAndRecord) {
    const std::string rec = temp_file("rec.json");
    const Result r = run("crowd --quiet --graph " + kGraph + " --agents 10 --seconds 5 --world 20x20 --record " + rec);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("0 outside fallbacks"), std::string::npos) << r.out;
    EXPECT_EQ(crowd::load_record(rec).tracks.size(), 10u);
    std::remove(rec.c_str());
}

// The motion metrics pose every agent from the mocap: printed and recorded when it is there, left out
// with the reason when a source cannot be read, and skipped on request - the run itself succeeds.
TEST(CrowdCli, MotionMetricsNeedTheMocap) {
    const std::string rec = temp_file("motion.json"), graph = temp_file("no_mocap_graph.json");
    nlohmann::json g = nlohmann::json::parse(test::slurp(kGraph));
    for (auto& source : g["sources"]) source["file"] = "no/such/folder/" + source["file"].get<std::string>();
    std::ofstream(graph) << g.dump();
    const std::string args = " --agents 4 --seconds 3 --world 10x10 --record " + rec;
    const Result missing = run("crowd --quiet --graph " + graph + args);
    ASSERT_EQ(missing.code, 0) << missing.err;
    EXPECT_NE(missing.out.find("motion: not measured ("), std::string::npos) << missing.out;
    EXPECT_FALSE(nlohmann::json::parse(test::slurp(rec))["metrics"].contains("motion"));
    const Result skipped = run("crowd --quiet --no-motion --graph " + kGraph + args);
    ASSERT_EQ(skipped.code, 0) << skipped.err;
    EXPECT_EQ(skipped.out.find("\nmotion"), std::string::npos) << skipped.out;  // the graph is "locomotion"
    if (!io::data_dir().empty()) {
        const Result r = run("crowd --quiet --graph " + kGraph + args);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("blended 0.25 s, feet locked: joint jump median / p99"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("planted feet (found contacts)"), std::string::npos) << r.out;
        const nlohmann::json m = nlohmann::json::parse(test::slurp(rec))["metrics"]["motion"];
        EXPECT_EQ(m["foot_contact"]["height"].get<double>(), 0.05);
        EXPECT_GT(m["raw"]["jump_start"]["p99"].get<double>(), m["blended"]["jump_start"]["p99"].get<double>());
        EXPECT_TRUE(m["blended"]["feet_locked"].get<bool>());
        EXPECT_TRUE(m["unlocked"]["foot_contacts"].contains("walk"));
    }
    std::remove(rec.c_str());
    std::remove(graph.c_str());
}

// The record file is the same, byte for byte, for another run and another thread count (wall times
// and the thread count are printed, not recorded).
TEST(CrowdCli, RecordDoesNotDependOnRunOrThreads) {
    const std::string args =
        "crowd --quiet --graph " + kGraph + " --agents 40 --seconds 10 --world 20x25 --seed 5 --record ";
    std::string text[3];
    const int threads[3] = {1, 2, 2};
    for (int k = 0; k < 3; ++k) {
        const std::string rec = temp_file("rec" + std::to_string(k) + ".json");
        const Result r = run(args + rec + " --threads " + std::to_string(threads[k]));
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find(std::to_string(threads[k]) + " threads"), std::string::npos) << r.out;
        text[k] = test::slurp(rec);
        std::remove(rec.c_str());
    }
    EXPECT_FALSE(text[0].empty());
    EXPECT_TRUE(text[1] == text[0]);
    EXPECT_TRUE(text[2] == text[0]);
}

// A goal crowd too (bottleneck: 30 agents through a door, where choice points of one frame meet and are
// evaluated again): 1, 2 and 3 threads write the same record, byte for byte (issue 46).
TEST(CrowdCli, ScenarioRecordDoesNotDependOnThreads) {
    const std::string args = "crowd --quiet --no-motion --graph " + kGraph + " --scenario " +
                             std::string(MOBB_SOURCE_DIR) + "/assets/scenarios/bottleneck.json --seed 2 --record ";
    std::string first;
    for (int threads : {1, 2, 3}) {
        const std::string rec = temp_file("scen" + std::to_string(threads) + ".json");
        const Result r = run(args + rec + " --threads " + std::to_string(threads));
        ASSERT_EQ(r.code, 0) << r.err;
        const std::string text = test::slurp(rec);
        std::remove(rec.c_str());
        ASSERT_NE(text.find("\"reevaluated\""), std::string::npos);
        if (threads == 1) first = text;
        EXPECT_TRUE(text == first) << threads << " threads";
    }
    EXPECT_EQ(first.find("\"reevaluated\": 0,"), std::string::npos) << "no choice point was evaluated again";
}

// --max-batch: a scenario's frames in batches of one choice point give the record of one batch a frame -
// every clip, plan and candidate - and only the work differs: nothing evaluated twice, each choice point's
// `pruned` counted against the broad phase of its own time. 0 is a usage error.
TEST(CrowdCli, MaxBatchChangesOnlyTheWork) {
    const std::string args = "crowd --quiet --no-motion --graph " + kGraph + " --scenario " +
                             std::string(MOBB_SOURCE_DIR) + "/assets/scenarios/bottleneck.json --seed 2 --record ";
    nlohmann::json records[2];
    for (int k : {0, 1}) {
        const std::string rec = temp_file("batch" + std::to_string(k) + ".json");
        const Result r = run(args + rec + (k == 1 ? " --max-batch 1" : ""));
        ASSERT_EQ(r.code, 0) << r.err;
        std::ifstream f(rec);
        records[k] = nlohmann::json::parse(f);
        std::remove(rec.c_str());
    }
    EXPECT_GT(records[0]["summary"]["reevaluated"].get<int>(), 0);
    EXPECT_EQ(records[1]["summary"]["reevaluated"].get<int>(), 0);
    for (nlohmann::json& j : records) {
        j.erase("summary");
        for (nlohmann::json& c : j["choices"]) c["pruned"] = 0;
    }
    EXPECT_TRUE(records[0] == records[1]);
    EXPECT_NE(run(args + temp_file("batch_none.json") + " --max-batch 0").code, 0);
}

// mobb record flow: evacuation_exit's 30 agents all leave the room through its door (x = 0) toward -x, each
// counted once, from its JSON record and its HDF5 record alike; a bad line is one error line, exit 1.
TEST(CrowdCli, RecordFlowThroughADoor) {
    const std::string args = "crowd --quiet --no-motion --graph " + kGraph + " --scenario " +
                             std::string(MOBB_SOURCE_DIR) + "/assets/scenarios/evacuation_exit.json --seed 1 --record ";
    const std::string json = temp_file("flow.json"), h5 = temp_file("flow.h5");
    ASSERT_EQ(run(args + json).code, 0);
    ASSERT_EQ(run(args + h5).code, 0);
    std::string first;
    for (const std::string& rec : {json, h5}) {
        const Result r = run("record flow " + rec + " --line x=0 --json");
        ASSERT_EQ(r.code, 0) << r.err;
        nlohmann::json j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j["agents"], 30);
        EXPECT_EQ(j["crossings"], 30);
        EXPECT_EQ(j["backward"], 30);
        EXPECT_GT(j["rate"].get<double>(), 0.1);
        EXPECT_GT(j["median_headway"].get<double>(), 0.0);
        j.erase("file");
        if (first.empty()) first = j.dump();
        EXPECT_EQ(j.dump(), first) << rec;
    }
    const Result bad = run("record flow " + json + " --line z=0");
    EXPECT_EQ(bad.code, 1);
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(bad.err, "error: --line: bad line 'z=0': expected x=METRES or y=METRES\n");
    for (const std::string& f : {json, h5}) std::remove(f.c_str());
}

// --record by extension: the HDF5 record of a run (its candidates asked for, as a JSON record keeps them)
// converts to its JSON record byte for byte, and back; a file cut short is refused in one line naming it,
// exit 1, nothing on stdout and no file written. (The motion metrics left out: a streamed HDF5 run keeps
// no clips to pose.)
TEST(CrowdCli, RecordConvertBothWays) {
    const std::string args =
        "crowd --quiet --no-motion --graph " + kGraph + " --agents 12 --seconds 6 --world 12x14 --record ";
    const std::string json = temp_file("conv.json"), h5 = temp_file("conv.h5"), back = temp_file("back.json"),
                      again = temp_file("again.h5"), cut = temp_file("cut.h5"), none = temp_file("none.json");
    ASSERT_EQ(run(args + json).code, 0);
    ASSERT_EQ(run(args + h5 + " --record-candidates").code, 0);
    const Result r = run("record convert " + h5 + " " + back);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("12 agents, 180 frames"), std::string::npos) << r.out;
    EXPECT_TRUE(test::slurp(back) == test::slurp(json));
    ASSERT_EQ(run("record convert " + json + " " + again).code, 0);
    ASSERT_EQ(run("record convert " + again + " " + back).code, 0);
    EXPECT_TRUE(test::slurp(back) == test::slurp(json));
    std::ofstream(cut, std::ios::binary) << test::slurp(h5).substr(0, 20000);
    const Result bad = run("record convert " + cut + " " + none);
    EXPECT_EQ(bad.code, 1);
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(bad.err.rfind("error: " + cut + ": ", 0), 0u) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_FALSE(std::ifstream(none).good());
    for (const std::string& f : {json, h5, back, again, cut}) std::remove(f.c_str());
}

// The choice points' candidates and their queries by the record's kind: a JSON record keeps them, an HDF5
// one only when asked. Without them the two kinds hold the same record, byte for byte once converted, its
// choice points there with their counts and empty candidate lists.
TEST(CrowdCli, CandidatesOnlyWhenAsked) {
    const std::string args =
        "crowd --quiet --no-motion --graph " + kGraph + " --agents 12 --seconds 6 --world 12x14 --record ";
    const std::string json = temp_file("cand.json"), bare = temp_file("bare.json"), h5 = temp_file("bare.h5"),
                      back = temp_file("bare_back.json");
    ASSERT_EQ(run(args + json).code, 0);
    ASSERT_EQ(run(args + bare + " --no-record-candidates").code, 0);
    ASSERT_EQ(run(args + h5).code, 0);
    ASSERT_EQ(run("record convert " + h5 + " " + back).code, 0);
    EXPECT_TRUE(test::slurp(back) == test::slurp(bare));
    const auto candidates = [](const std::string& file) {
        std::size_t n = 0, queries = 0;
        const nlohmann::json record = nlohmann::json::parse(test::slurp(file));
        for (const auto& c : record["choices"]) {
            n += c["candidates"].size();
            queries += c["queries"].get<std::size_t>();
        }
        return std::pair{n, queries};
    };
    const auto [kept, counted] = candidates(json);
    EXPECT_GT(kept, 0u);
    EXPECT_EQ(candidates(bare), std::pair(std::size_t(0), counted));  // the counts stay
    const Result r = run("crowd --quiet --graph " + kGraph + " --agents 3 --seconds 1 --record-candidates");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "crowd: --record-candidates and --no-record-candidates go with --record\n");
    for (const std::string& f : {json, bare, h5, back}) std::remove(f.c_str());
}

// One line on stderr, starting "error: FILE: " and holding `part`; exit 1, nothing on stdout.
void expect_refused(const Result& r, const std::string& file, const std::string& part) {
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.rfind("error: " + file + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// A JSON record is held whole: one that would need more memory than MOBB_JSON_RECORD_MB (1 MB here; 2 GB
// unless set) is refused before the run - exit 1, one line naming the file, no file - and before it is
// read, by `record convert` and `render`; an HDF5 record streams and is not limited. 10 agents x 30 s: some
// 1 MB of JSON, estimated at 8 MB of memory to write.
TEST(CrowdCli, AJsonRecordPastTheMemoryLimitIsRefused) {
    const std::string json = temp_file("big.json"), h5 = temp_file("big.h5"), back = temp_file("big_back.json"),
                      png = temp_file("big.png");
    const std::string args = "crowd --quiet --no-motion --graph " + kGraph + " --agents 10 --seconds 30 --world 20x20 ";
    ::setenv("MOBB_JSON_RECORD_MB", "1", 1);
    expect_refused(run(args + "--record " + json), json, "(MOBB_JSON_RECORD_MB); record to .h5 instead");
    EXPECT_FALSE(std::ifstream(json).good());
    ASSERT_EQ(run(args + "--record " + h5).code, 0);
    expect_refused(run("record convert " + h5 + " " + back), back, "record to .h5 instead");
    EXPECT_FALSE(std::ifstream(back).good());
    ::setenv("MOBB_JSON_RECORD_MB", "100", 1);
    ASSERT_EQ(run("record convert " + h5 + " " + json).code, 0);
    ::setenv("MOBB_JSON_RECORD_MB", "1", 1);
    const std::string convert = "mobb record convert " + json + " ";
    expect_refused(run("record convert " + json + " " + back), json, convert);
    expect_refused(run("render --crowd " + json + " --width 64 --height 64 --out " + png), json, convert);
    EXPECT_FALSE(std::ifstream(png).good());
    ::setenv("MOBB_JSON_RECORD_MB", "a lot", 1);
    expect_refused(run(args + "--record " + json), "MOBB_JSON_RECORD_MB", "expected a positive number");
    ::unsetenv("MOBB_JSON_RECORD_MB");
    for (const std::string& f : {json, h5, back, png}) std::remove(f.c_str());
}

TEST(CrowdCli, ScenarioRunsToItsGoals) {
    const std::string rec = temp_file("scenario.json");
    const Result r = run("crowd --quiet --graph " + kGraph + " --scenario " + std::string(MOBB_SOURCE_DIR) +
                         "/assets/scenarios/oncoming.json --record " + rec);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("scenario oncoming: 2 agents", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("2 of 2 reached"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("PASSED"), std::string::npos) << r.out;
    const crowd::Record record = crowd::load_record(rec);
    EXPECT_EQ(record.scenario, "oncoming");
    EXPECT_EQ(record.select, "goal");
    ASSERT_EQ(record.tracks[0].goals.size(), 1u);
    const nlohmann::json j = nlohmann::json::parse(test::slurp(rec));
    EXPECT_TRUE(j["metrics"]["passed"].get<bool>());
    EXPECT_EQ(j["world"].size(), 4u);
    std::remove(rec.c_str());
}

TEST(CrowdCli, BenchCrowdWritesItsTables) {
    const std::string json = temp_file("crowd.json"), png = temp_file("crowd.png");
    const Result r = run("bench crowd --quick --quiet --graph " + kGraph + " --json " + json + " --png " + png);
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* part :
         {"### Wandering crowds", "### Scenarios", "Targets (issues 10, 28 and 30)", "### Motion", "fallbacks <= 0.5 %",
          "time to goal <= 1.5x the straight line", "time to goal / straight at walking speed"})
        EXPECT_NE(r.out.find(part), std::string::npos) << part;
    const nlohmann::json j = nlohmann::json::parse(test::slurp(json));
    EXPECT_EQ(j["workload"], "crowd");
    EXPECT_EQ(j["wander"].size(), 2u);
    EXPECT_EQ(j["scenarios"].size(), 2u);
    EXPECT_FALSE(j["targets"].empty());
    EXPECT_TRUE(j["wander"][0]["metrics"].contains("idle_share"));
    EXPECT_GT(test::slurp(png).size(), 1000u);
    std::remove(json.c_str());
    std::remove(png.c_str());
}

TEST(CrowdCli, ScenarioErrors) {
    const std::string bad = temp_file("bad_scenario.json");
    std::ofstream(bad) << R"({"world": [0, 0, 10, 10], "time_limit": 5,
        "agents": [{"start": [3, 5], "goal": [8, 5]}, {"start": [3.5, 5], "goal": [8, 8]}]})";
    Result r = run("crowd --quiet --graph " + kGraph + " --scenario " + bad);
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.err.find("error: " + bad + ": "), 0u) << r.err;
    EXPECT_NE(r.err.find("start closer than"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty());
    std::ofstream(bad) << "{ not json";
    r = run("crowd --quiet --graph " + kGraph + " --scenario " + bad);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(bad + ": not valid JSON"), std::string::npos) << r.err;
    r = run("crowd --quiet --graph " + kGraph + " --scenario " + bad + " --agents 5");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--agents does not go with --scenario"), std::string::npos) << r.err;
    std::remove(bad.c_str());
}

TEST(CrowdCli, ErrorsAndExitCodes) {
    Result r = run("crowd --quiet --graph " + kGraph + " --world 30by40");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("--world"), std::string::npos);
    EXPECT_TRUE(r.out.empty());
    r = run("crowd --quiet --graph /nonexistent/g.json");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("/nonexistent/g.json"), std::string::npos);
    r = run("crowd --select nearest");
    EXPECT_EQ(r.code, 2);
    r = run("graph build /nonexistent/a.bvh --out /tmp/never.json");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("/nonexistent/a.bvh"), std::string::npos);
    r = run("graph build /nonexistent/a.bvh --out /tmp/never.json --centre middle");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--centre"), std::string::npos) << r.err;
    r = run("bench");
    EXPECT_EQ(r.code, 2);
}

// --tune sets any CrowdTuning field by name: the run changes with it, and a bad one is a usage error.
TEST(CrowdCli, TuneSetsAFieldByName) {
    const std::string base = "crowd --quiet --graph " + kGraph + " --scenario " + std::string(MOBB_SOURCE_DIR) +
                             "/assets/scenarios/crossing.json --record ";
    const std::string plain = temp_file("tune_plain.json"), tuned = temp_file("tune_field.json"),
                      flag = temp_file("tune_flag.json");
    ASSERT_EQ(run(base + plain).code, 0);
    ASSERT_EQ(run(base + tuned + " --tune look_ahead=off").code, 0);
    ASSERT_EQ(run(base + flag + " --no-look-ahead").code, 0);
    EXPECT_EQ(test::slurp(tuned), test::slurp(flag)) << "the flag and the field are one switch";
    EXPECT_NE(test::slurp(tuned), test::slurp(plain)) << "the look-ahead changes the record";
    for (const std::string& f : {plain, tuned, flag}) std::remove(f.c_str());
    for (const char* bad : {"look_ahead_budget=many", "no_such_field=1", "look_ahead", "goal_walking=nan"}) {
        const Result r = run(base + plain + " --tune " + bad);
        EXPECT_EQ(r.code, 2) << bad;
        EXPECT_EQ(r.err.rfind("crowd: --tune ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(r.out.empty());
        EXPECT_FALSE(std::ifstream(plain).good()) << "no record for a usage error";
    }
}

}  // namespace
}  // namespace mobb
