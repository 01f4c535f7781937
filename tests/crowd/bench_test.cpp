// Smoke runs of the benchmarks (shape of the output, not timing) and the crowd layer's command line.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "data.h"
#include "files.h"
#include "mobb/crowd/bench_tables.h"
#include "mobb/crowd/record.h"

namespace mobb::crowd {
namespace {

using test::temp_file;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";
// Issue 5's row order: paper rows, brute force, best scan, FCL, mobb (then frame stepping in Table 1).
const std::vector<std::string> kRows = {"MOBB 1 level", "UMOBB 1 level", "MOBB",      "UMOBB", "Hybrid 1",
                                        "Hybrid 2",     "brute force",   "best scan", "FCL",   "mobb"};

void expect_shape(const BenchTable& t, bool stepping) {
    ASSERT_EQ(t.rows.size(), kRows.size() + (stepping ? 1 : 0));
    for (std::size_t k = 0; k < kRows.size(); ++k) {
        const MethodRow& r = t.rows[k];
        EXPECT_EQ(r.method, kRows[k]);
        if (r.method == "FCL") {  // optional peer, conservative: its own positives and disagreements
            EXPECT_EQ(r.measured, fcl_built());
            if (!r.measured) {
                EXPECT_NE(r.note.find("without FCL"), std::string::npos);
            }
            continue;
        }
        EXPECT_GT(r.queries, 0u);
        EXPECT_GT(r.us_per_query, 0.0);
        EXPECT_GT(r.x_mobb, 0.0);
        EXPECT_EQ(r.disagreements, 0u) << r.method << " disagrees with brute force";
        if (r.queries == t.rows.front().queries) {
            EXPECT_DOUBLE_EQ(r.positive, t.rows.front().positive);
        }
    }
    EXPECT_DOUBLE_EQ(t.rows[kRows.size() - 1].x_mobb, 1.0);
    EXPECT_FALSE(t.targets.empty());
    EXPECT_EQ(t.rows[0].tests3d, 0.0);  // MOBB 1 level: 2D root only
    EXPECT_EQ(t.rows[1].tests2d, 0.0);  // UMOBB 1 level: 3D root only
    EXPECT_GT(t.rows[2].tests2d, 0.0);
    const nlohmann::json j = nlohmann::json::parse(table_json(t));
    ASSERT_EQ(j["rows"].size(), t.rows.size());
    for (const auto& row : j["rows"]) {
        EXPECT_TRUE(row["method"].is_string());
        if (row["method"] != "FCL" || fcl_built()) {
            EXPECT_TRUE(row["us_per_query"].is_number()) << row["method"];
        }
    }
    EXPECT_EQ(j["targets"].size(), t.targets.size());
    const std::string md = table_markdown(t);
    EXPECT_NE(md.find("| Method | Time (us) | x mobb | #2D | #3D | #sample |"), std::string::npos);
    EXPECT_NE(md.find("| Hybrid 2 |"), std::string::npos);
    EXPECT_NE(md.find("| mobb | "), std::string::npos);
    EXPECT_NE(md.find("Targets (issue 5)"), std::string::npos);
}

TEST(Bench, Table1QuickShape) {
    Table1Options o;
    o.graph = kGraph;
    o.agents = 20;
    o.seconds = 10;
    o.passes = 1;
    const BenchTable t = run_table1(o);
    expect_shape(t, true);
    EXPECT_EQ(t.rows.back().method, "frame stepping");
    EXPECT_EQ(t.workload, "table1");
    const std::string png = temp_file("table1.png");
    write_table_png(t, png);
    std::ifstream f(png, std::ios::binary);
    char magic[4] = {};
    f.read(magic, 4);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG");
    std::remove(png.c_str());
}

TEST(Bench, Table2QuickShapeAndRootShare) {
    MOBB_REQUIRE_MOCAP();
    Table2Options o;
    o.graph = kGraph;
    o.tests = 1000;
    o.root_share = 0.8;
    o.passes = 1;
    o.motions = 4;
    const BenchTable t = run_table2(o);
    expect_shape(t, false);
    EXPECT_EQ(t.rows.front().queries, 1000u);
    EXPECT_NE(t.notes.at("root overlap target").find("80.0 %"), std::string::npos);
}

TEST(Bench, Table2SynthShape) {
    Table2Options o;
    o.graph = kGraph;
    o.synth = true;
    o.motions = 3;
    o.synth_seconds = 20;
    o.tests = 500;
    o.root_share = 0.5;
    o.passes = 1;
    o.slow_queries = 50;
    const BenchTable t = run_table2(o);
    expect_shape(t, false);
    EXPECT_NE(t.title.find("motion-graph sequences"), std::string::npos);
    EXPECT_EQ(t.workload, "synth20");
    EXPECT_EQ(t.rows[6].timed_queries, 50u);  // brute force: timed on a prefix, answers all
    EXPECT_EQ(t.rows[6].queries, 500u);
}

TEST(Bench, QuerySetRoundTrip) {
    QuerySet set;
    set.clips.push_back({1.0 / 30.0, {{0.1, 0.2, 0.3}, {1.0 / 3.0, -2.5e-7, 0.25}}});
    set.queries.push_back({0, 0, {0.5, 1.0 / 7.0, 3.0, 0.1}, {-1, 2, -3.1, 0}});
    const std::string file = temp_file("set.txt");
    save_query_set(set, file);
    const QuerySet back = load_query_set(file);
    ASSERT_EQ(back.clips.size(), 1u);
    ASSERT_EQ(back.queries.size(), 1u);
    EXPECT_EQ(back.clips[0].dt, set.clips[0].dt);
    EXPECT_EQ(back.clips[0].samples[1].x, set.clips[0].samples[1].x);
    EXPECT_EQ(back.clips[0].samples[1].y, set.clips[0].samples[1].y);
    EXPECT_EQ(back.queries[0].pa.y, set.queries[0].pa.y);
    EXPECT_EQ(back.queries[0].pb.theta, set.queries[0].pb.theta);
    std::remove(file.c_str());
    EXPECT_THROW(load_query_set(file), std::runtime_error);
}

TEST(Bench, MethodsByName) {
    for (const auto& m : bench_methods()) EXPECT_EQ(method_by_name(m->name())->name(), m->name());
    EXPECT_THROW(method_by_name("nearest"), std::invalid_argument);
}

TEST(Bench, ScaleQuickShape) {
    ScaleOptions o;
    o.graph = kGraph;
    o.agents = {8, 16};
    o.seconds = 4;
    o.threads = 2;
    const ScaleTable t = run_scale(o);
    ASSERT_EQ(t.rows.size(), 2u);
    for (const ScaleRow& r : t.rows) {
        EXPECT_TRUE(r.identical) << r.agents << " agents: " << r.digest_1 << " vs " << r.digest_n;
        EXPECT_EQ(r.contacts_unexcused, 0u);
        EXPECT_GT(r.choice_points, 0u);
        EXPECT_EQ(r.threads, 2);
    }
    EXPECT_NEAR(t.rows[1].width * t.rows[1].height, 16 * o.area_per_agent, 1e-9);
    EXPECT_EQ(t.targets.size(), 3u);
    const nlohmann::json j = nlohmann::json::parse(scale_json(t));
    EXPECT_EQ(j["workload"], "scale");
    for (const auto& row : j["rows"]) {
        EXPECT_TRUE(row["method"].is_string());
        EXPECT_TRUE(row["us_per_query"].is_number());
    }
    EXPECT_NE(scale_markdown(t).find("| agents |"), std::string::npos);
}

#ifdef MOBB_EXE
struct Result {
    int code;
    std::string out, err;
};

Result run(const std::string& args) {
    const std::string err = temp_file("crowd_cli_err.txt");
    const std::string cmd = std::string(MOBB_EXE) + " " + args + " 2>" + err;
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    char buf[4096];
    for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    const int status = pclose(p);
    return {WEXITSTATUS(status), out, test::slurp(err)};
}

TEST(CrowdCli, BenchCommandsPrintTables) {
    const std::string json = temp_file("t1.json"), png = temp_file("t1.png");
    const Result r = run("bench table1 --quick --quiet --graph " + kGraph + " --json " + json + " --png " + png);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("| MOBB 1 level |"), std::string::npos);
    EXPECT_NE(r.out.find("| frame stepping |"), std::string::npos);
    EXPECT_NE(r.out.find("| best scan |"), std::string::npos);
    EXPECT_NE(r.out.find("| FCL |"), std::string::npos);
    EXPECT_NE(r.out.find("| mobb |"), std::string::npos);
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

TEST(CrowdCli, Issue5Workloads) {
    const std::string json = temp_file("w.json"), set = temp_file("w.queries");
    for (const std::string w : {"synth42", "synth120"}) {
        const Result r = run("bench " + w + " --quick --quiet --motions 2 --tests 300 --slow-queries 20 --graph " + kGraph +
                             " --json " + json + " --save-queries " + set);
        ASSERT_EQ(r.code, 0) << w << ": " << r.err;
        EXPECT_NE(r.out.find("| mobb |"), std::string::npos);
        expect_json_rows(json, w);
        EXPECT_EQ(load_query_set(set).queries.size(), 300u);
    }
    const Result r = run("bench scale --quick --quiet --graph " + kGraph + " --json " + json);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("| 40 |"), std::string::npos);
    expect_json_rows(json, "scale");
    std::remove(json.c_str());
    std::remove(set.c_str());
}

TEST(CrowdCli, CrowdPrintsSummaryAndRecord) {
    const std::string rec = temp_file("rec.json");
    const Result r = run("crowd --quiet --graph " + kGraph + " --agents 10 --seconds 5 --world 20x20 --record " + rec);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("0 outside fallbacks"), std::string::npos) << r.out;
    EXPECT_EQ(load_record(rec).tracks.size(), 10u);
    std::remove(rec.c_str());
}

// The record file is the same, byte for byte, for another run and another thread count (wall times
// and the thread count are printed, not recorded).
TEST(CrowdCli, RecordDoesNotDependOnRunOrThreads) {
    const std::string args = "crowd --quiet --graph " + kGraph + " --agents 40 --seconds 10 --world 20x25 --seed 5 --record ";
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
    r = run("bench");
    EXPECT_EQ(r.code, 2);
}
#endif

}  // namespace
}  // namespace mobb::crowd
