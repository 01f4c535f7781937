// Smoke runs of the benchmark library (shape of the output, not timing), its methods, workloads and files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "data.h"
#include "files.h"
#include "method.h"
#include "mobb/crowd/sim/crowd.h"
#include "peak_memory.h"
#include "report.h"
#include "steersuite_cases.h"
#include "workloads.h"

namespace mobb::bench {
namespace {

using test::temp_file;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";
// The tables' row order: paper rows, brute force, best scan, FCL, circle sweep (then frame stepping in Table 1).
const std::vector<std::string> kRows = {"MOBB 1 level", "UMOBB 1 level", "MOBB",      "UMOBB", "Hybrid 1",
                                        "Hybrid 2",     "brute force",   "best scan", "FCL",   "circle sweep"};

bool fcl_built() { return fcl_method()->unavailable().empty(); }

void expect_shape(const BenchTable& t, bool stepping) {
    ASSERT_EQ(t.rows.size(), kRows.size() + (stepping ? 1 : 0));
    for (std::size_t k = 0; k < kRows.size(); ++k) {
        const MethodRow& r = t.rows[k];
        EXPECT_EQ(r.label, kRows[k]);
        ASSERT_TRUE(r.method.has_value());
        EXPECT_EQ(r.label, label(*r.method));
        if (r.method == Method::Fcl) {  // optional peer, conservative: its own positives and disagreements
            EXPECT_EQ(r.measured, fcl_built());
            if (!r.measured) {
                EXPECT_NE(r.note.find("without FCL"), std::string::npos);
            }
            continue;
        }
        EXPECT_GT(r.queries, 0u);
        EXPECT_GT(r.us_per_query, 0.0);
        EXPECT_GT(r.x_sweep, 0.0);
        EXPECT_EQ(r.disagreements, 0u) << r.label << " disagrees with brute force";
        if (r.queries == t.rows.front().queries) {
            EXPECT_DOUBLE_EQ(r.positive, t.rows.front().positive);
        }
    }
    EXPECT_DOUBLE_EQ(t.rows[kRows.size() - 1].x_sweep, 1.0);
    EXPECT_FALSE(t.targets.empty());
    EXPECT_EQ(t.rows[0].tests3d, 0.0);  // MOBB 1 level: 2D root only
    EXPECT_EQ(t.rows[1].tests2d, 0.0);  // UMOBB 1 level: 3D root only
    EXPECT_GT(t.rows[2].tests2d, 0.0);
    const nlohmann::json j = nlohmann::json::parse(table_json(t));
    ASSERT_EQ(j["rows"].size(), t.rows.size());
    int defaults = 0;
    for (const auto& row : j["rows"]) {
        EXPECT_TRUE(row["method"].is_string());
        if (row["method"] != "FCL" || fcl_built()) {
            EXPECT_TRUE(row["us_per_query"].is_number()) << row["method"];
        }
        ASSERT_TRUE(row["default"].is_boolean()) << row["method"];
        if (row["default"]) {
            ++defaults;
            EXPECT_EQ(row["method"], label(kDefaultMethod));
        }
    }
    EXPECT_EQ(defaults, 1);  // the library's default query's row, and only it
    EXPECT_EQ(j["targets"].size(), t.targets.size());
    const std::string md = table_markdown(t);
    EXPECT_NE(md.find("| Method | Time (us) | x sweep | #2D | #3D | #sample |"), std::string::npos);
    EXPECT_NE(md.find("| Hybrid 2 |"), std::string::npos);
    EXPECT_NE(md.find("| circle sweep | "), std::string::npos);
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
    EXPECT_EQ(t.rows.back().label, "frame stepping");
    EXPECT_FALSE(t.rows.back().method.has_value());
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

// One name table: every method by its key and by its label, made as itself; tree methods named as
// the core names their tree types.
TEST(Bench, MethodsByName) {
    for (int k = 0; k < kMethodCount; ++k) {
        const Method m = Method(k);
        EXPECT_EQ(parse_method(key(m)), m);
        EXPECT_EQ(parse_method(label(m)), m);
        EXPECT_EQ(make_method(m)->method(), m);
        if (const auto type = tree_type(m)) {
            EXPECT_STREQ(key(m), to_string(*type));
        }
    }
    EXPECT_EQ(parse_method("sweep"), Method::Sweep);
    EXPECT_STREQ(label(Method::Mobb1), "MOBB 1 level");
    EXPECT_THROW(parse_method("nearest"), std::invalid_argument);
    EXPECT_EQ(table_methods().size(), std::size_t(kMethodCount));
}

// The workloads' generators are deterministic, and the paper's random tests land the second clip's
// centre within the radius of the first's.
TEST(Bench, RandomTestsAreDeterministicAndWithinTheRadius) {
    std::vector<Path> clips(2);
    for (int k = 0; k < 50; ++k) {
        clips[0].samples.push_back({0.05 * k, 0, 0.3});
        clips[1].samples.push_back({0, 0.04 * k, 0.3});
    }
    const auto a = random_tests(clips, 2.0, 200, 7), b = random_tests(clips, 2.0, 200, 7);
    ASSERT_EQ(a.size(), 200u);
    for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].pb.x, b[k].pb.x);
        EXPECT_EQ(a[k].pb.t0, b[k].pb.t0);
        const Path &pa = clips[std::size_t(a[k].a)], &pb = clips[std::size_t(a[k].b)];
        const Rigid2 m = Rigid2::of(a[k].pb);
        double cx = 0, cy = 0;  // b's centre, placed
        for (const Sample& s : pb.samples)
            cx += m.apply_x(s.x, s.y) / double(pb.size()), cy += m.apply_y(s.x, s.y) / double(pb.size());
        const double ax = pa.samples.back().x / 2, ay = pa.samples.back().y / 2;
        EXPECT_LE(std::hypot(cx - ax, cy - ay), 2.0 + 1e-9);
        EXPECT_GE(a[k].pb.t0, -pb.duration());
        EXPECT_LE(a[k].pb.t0, pa.duration());
    }
    const std::vector<Tree> trees = mobb_trees(clips);
    EXPECT_GT(root_share(trees, random_tests(clips, 0.5, 500, 1)), root_share(trees, random_tests(clips, 20, 500, 1)));
}

// The scale workload keeps no record: its digest, made as the run streams, must be the whole record's.
TEST(Bench, StreamedDigestEqualsTheRecords) {
    const crowd::MotionGraph g = crowd::load_graph(kGraph);
    const crowd::NarrowPhase narrow = crowd::NarrowPhase::sweep(g);
    crowd::CrowdOptions o;
    o.agents = 12;
    o.world.x1 = 12;
    o.world.y1 = 16;
    o.seconds = 5;
    const crowd::CrowdRun whole = crowd::run_crowd(g, narrow, o);
    DigestSink sink;
    o.sink = &sink;
    crowd::run_crowd(g, narrow, o);
    EXPECT_EQ(sink.digest(), record_digest(whole.record));
    o.seed = 2;  // another run, another digest
    DigestSink other;
    o.sink = &other;
    crowd::run_crowd(g, narrow, o);
    EXPECT_NE(other.digest(), sink.digest());
}

TEST(Bench, PeakMemorySeesAnAllocation) {
    if (!reset_peak_memory()) GTEST_SKIP() << "this system cannot reset the peak (no /proc/self/clear_refs)";
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer keeps freed blocks resident (its quarantine), so the peak cannot fall";
#endif
    const std::int64_t before = peak_memory_bytes();
    ASSERT_GT(before, 0);
    std::vector<char> block(std::size_t(64) << 20, 1);  // 64 MB, touched
    EXPECT_GE(peak_memory_bytes(), before + (std::int64_t(60) << 20)) << int(block[block.size() / 2]);
    block = {};
    block.shrink_to_fit();
    reset_peak_memory();
    EXPECT_LT(peak_memory_bytes(), before + (std::int64_t(32) << 20));
}

TEST(Bench, ScaleQuickShape) {
    ScaleOptions o;
    o.graph = kGraph;
    o.agents = {8, 16};
    o.seconds = 4;
    o.threads = {1, 2};
    const ScaleTable t = run_scale(o);
    ASSERT_EQ(t.rows.size(), 2u);
    for (const ScaleRow& r : t.rows) {
        EXPECT_TRUE(r.identical) << r.agents << " agents: " << r.digest_1 << " vs " << r.digest_n;
        EXPECT_EQ(r.contacts_unexcused, 0u);
        EXPECT_GT(r.choice_points, 0u);
        EXPECT_EQ(r.threads, 2);
        EXPECT_TRUE(r.one_thread);
        EXPECT_GT(r.wall_seconds_n, 0);
        ASSERT_EQ(r.by_threads.size(), 2u);
        EXPECT_EQ(r.by_threads[0].threads, 1);
        EXPECT_EQ(r.by_threads[1].threads, 2);
        EXPECT_EQ(r.by_threads[1].sim_seconds, r.sim_seconds_n);
        EXPECT_FALSE(r.by_threads[0].serial_share.has_value());
    }
    EXPECT_EQ(t.threads, std::vector<int>({1, 2}));
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

// Sizes from parallel_only_from run the last thread count only: their other columns are empty.
TEST(Bench, ScaleLargeSizesRunTheLastCountOnly) {
    ScaleOptions o;
    o.graph = kGraph;
    o.agents = {8, 16};
    o.seconds = 2;
    o.threads = {1, 2, 3};
    o.repeats = 1;
    o.parallel_only_from = 16;
    const ScaleTable t = run_scale(o);
    ASSERT_EQ(t.rows.size(), 2u);
    ASSERT_EQ(t.rows[0].by_threads.size(), 3u);
    EXPECT_EQ(t.rows[0].by_threads[2].threads, 3);
    EXPECT_TRUE(t.rows[0].by_threads[2].serial_share.has_value() || t.rows[0].by_threads[2].cd_seconds <= 0);
    ASSERT_EQ(t.rows[1].by_threads.size(), 1u);
    EXPECT_EQ(t.rows[1].by_threads[0].threads, 3);
    EXPECT_EQ(t.rows[1].by_threads[0].speedup, 0);
    EXPECT_FALSE(t.rows[1].one_thread);
    const std::string md = scale_markdown(t);
    EXPECT_NE(md.find("| 16 x 2: simulation s | - | - | "), std::string::npos) << md;
    EXPECT_NE(md.find("| speed-up over 1 thread | - | - | - |"), std::string::npos) << md;
}

// Amdahl's law run backwards: times made from a known serial share give it back, from any reference.
TEST(Bench, SerialShareInvertsAmdahl) {
    const auto time = [](double s, int p) { return 10.0 * (s + (1 - s) / p); };
    for (double s : {0.0, 0.03, 0.25, 1.0}) {
        EXPECT_NEAR(*serial_share(1, time(s, 1), 2, time(s, 2)), s, 1e-12) << s;
        EXPECT_NEAR(*serial_share(1, time(s, 1), 16, time(s, 16)), s, 1e-12) << s;
        EXPECT_NEAR(*serial_share(2, time(s, 2), 8, time(s, 8)), s, 1e-12) << s;
    }
    EXPECT_NEAR(*serial_share(1, 5.55, 2, 4.09), 2 * 4.09 / 5.55 - 1, 1e-12);  // Karp-Flatt at p = 2
    EXPECT_FALSE(serial_share(2, 4.0, 2, 3.0).has_value());
    EXPECT_FALSE(serial_share(1, 0.0, 2, 3.0).has_value());
}

// Two test cases written here in SteerSuite's schema: one agent walking 6 m to its goal (passes), and
// one whose goal lies inside a closed box of obstacles (never reached), each with two seeds; a file
// that is not a test case; and a map without agents, which imports with nothing to judge.
TEST(Bench, SteerSuiteCasesJudged) {
    const std::string dir = temp_file("steersuite_cases");
    std::filesystem::create_directories(dir);
    const auto write = [&](const std::string& name, const std::string& items) {
        std::ofstream(dir + "/" + name) << "<SteerBenchTestCase>\n<header> <version>1.0</version> <name>" << name
                                        << "</name>\n<worldBounds> <xmin>-10</xmin> <xmax>10</xmax> <ymin>0</ymin> "
                                           "<ymax>0</ymax> <zmin>-10</zmin> <zmax>10</zmax> </worldBounds> </header>\n"
                                        << items << "</SteerBenchTestCase>\n";
    };
    const auto agent = [](double goal_x, double goal_z) {
        return "<agent> <initialConditions> <radius>0.5</radius> <position> <x>-3</x> <y>0</y> <z>0</z> "
               "</position> <direction> <x>1</x> <y>0</y> <z>0</z> </direction> <speed>0</speed> "
               "</initialConditions> <goalSequence> <seekStaticTarget> <targetLocation> <x>" +
               std::to_string(goal_x) + "</x> <y>0</y> <z>" + std::to_string(goal_z) +
               "</z> </targetLocation> <desiredSpeed>1.3</desiredSpeed> <timeDuration>1000</timeDuration> "
               "</seekStaticTarget> </goalSequence> </agent>\n";
    };
    const auto box = [](double x0, double x1, double z0, double z1) {
        return "<obstacle> <xmin>" + std::to_string(x0) + "</xmin> <xmax>" + std::to_string(x1) +
               "</xmax> <ymin>0</ymin> <ymax>1</ymax> <zmin>" + std::to_string(z0) + "</zmin> <zmax>" +
               std::to_string(z1) + "</zmax> </obstacle>\n";
    };
    write("a_open.xml", agent(3, 0));
    write("b_boxed.xml",
          agent(6, 6) + box(4, 8, 3.5, 4) + box(4, 8, 8, 8.5) + box(3.5, 4, 3.5, 8.5) + box(8, 8.5, 3.5, 8.5));
    std::ofstream(dir + "/c_broken.xml") << "<SteerBenchTestCase>\n";
    write("d_map.xml", box(4, 8, 3.5, 4));
    SteerSuiteOptions o;
    o.graph = kGraph;
    o.cases = {dir + "/a_open.xml", dir + "/b_boxed.xml", dir + "/c_broken.xml", dir + "/d_map.xml"};
    o.seeds = {1, 2};
    const SteerSuiteTable t = run_steersuite(o);
    ASSERT_EQ(t.rows.size(), 8u);
    for (int k : {0, 1}) {
        EXPECT_TRUE(t.rows[std::size_t(k)].verdict.passed) << t.rows[std::size_t(k)].verdict.reason;
        EXPECT_EQ(t.rows[std::size_t(k)].agents, 1);
        EXPECT_GT(t.rows[std::size_t(k)].metrics.time_ratio, 0.5);
    }
    for (int k : {2, 3}) {
        EXPECT_EQ(t.rows[std::size_t(k)].verdict.never, 1);
        EXPECT_EQ(t.rows[std::size_t(k)].metrics.contacts, 0u);
    }
    for (int k : {4, 5}) {
        EXPECT_NE(t.rows[std::size_t(k)].error.find("c_broken.xml"), std::string::npos);
        EXPECT_FALSE(t.rows[std::size_t(k)].imported);
    }
    for (int k : {6, 7}) {
        EXPECT_TRUE(t.rows[std::size_t(k)].imported);
        EXPECT_EQ(t.rows[std::size_t(k)].agents, 0);
    }
    EXPECT_EQ(t.cases, 3);  // the map has nothing to judge; the broken file fails
    EXPECT_EQ(t.cases_passed, 1);
    EXPECT_EQ(t.empty, std::vector<std::string>{"d_map"});
    EXPECT_EQ(t.targets.front().measured, 6);  // of 8 runs, the broken file's two do not import
    const nlohmann::json j = nlohmann::json::parse(steersuite_json(t));
    EXPECT_EQ(j["cases_passed"], 1);
    EXPECT_EQ(j["cases_without_agents"][0], "d_map");
    EXPECT_EQ(j["rows"][2]["judge"]["never"], 1);
    const std::string md = steersuite_markdown(t);
    EXPECT_NE(md.find("1 of 3 cases pass on every seed. d_map imports without an agent"), std::string::npos);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mobb::bench
