// Record files: a run written as JSON and as HDF5 holds the same record, every field (the HDF5 file read
// back writes the JSON text byte for byte), either way round; a truncated or damaged HDF5 file is
// refused with one line naming the file (and the block, where one is damaged), never a crash.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <tuple>

#include <gtest/gtest.h>

#include "files.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/record/record_file.h"
#include "mobb/crowd/record/record_reader.h"
#include "mobb/crowd/sim/crowd.h"
#include "record_runs.h"

namespace mobb::crowd {
namespace {

using test::committed_graph;
using test::run_written;
using test::slurp;
using Written = test::WrittenRun;

const MotionGraph& graph() { return committed_graph(); }

// A wandering crowd in a room with an obstacle (queries against agents, ground, walls, the obstacle).
const Written& wandering() {
    static const Written w = run_written(test::crowd_beside_obstacle(8));
    return w;
}

// Goal agents that leave at their goal (goals, left_frame, at_goal, intended clips).
const Written& leaving() {
    static const Written w = run_written(test::leaving_crowd(), test::fan_in_exit_name());
    return w;
}

// The wandering crowd without its candidates and their queries (CrowdOptions::record_queries off, as an
// HDF5 record of `mobb crowd` is unless asked).
const Written& bare() {
    static const Written w = [] {
        CrowdOptions o = wandering().options;
        o.record_queries = false;
        return run_written(o);
    }();
    return w;
}

// The error reading `file` gives ("" when it reads).
std::string read_error(const std::string& file) {
    return test::file_error(file, [&] { read_record_file(file); });
}

std::string text_of(const RecordFile& r) { return record_to_text(r.record, r.summary_json, r.metrics_json); }

// The same run streamed to an HDF5 file as it goes (CrowdOptions::sink), its metrics computed on the
// stream: the file read back.
RecordFile streamed(const Written& w, const std::string& file, int threads = 1) {
    CrowdOptions o = w.options;
    o.threads = threads;
    H5RecordWriter out(file, w.record.graph, w.record.scenario);
    o.sink = &out;
    CrowdRun run = run_crowd(graph(), NarrowPhase::sweep(graph()), o);
    EXPECT_TRUE(run.record.choices.empty() && run.record.tracks[0].samples.empty());  // nothing kept
    run.record.scenario = w.record.scenario;
    out.finish(run.record, summary_json(run.summary), metrics_json(run.metrics.value()));
    return read_record_file(file);
}

TEST(RecordFile, Hdf5HoldsEveryFieldOfTheJson) {
    for (const Written* w : {&wandering(), &leaving()}) {
        const std::string json = record_to_text(w->record, w->summary, w->metrics);
        const std::string h5 = test::temp_file("run.h5");
        write_record_file(h5, w->record, w->summary, w->metrics);
        EXPECT_EQ(text_of(read_record_file(h5)), json);
        // Streamed as the run goes, on one thread and on two.
        for (int threads : {1, 2}) {
            const RecordFile s = streamed(*w, h5, threads);
            EXPECT_EQ(s.note, "");
            EXPECT_EQ(text_of(s), json) << threads << " threads";
        }
        // And back: the JSON file read and written as HDF5 again, then as JSON.
        const std::string j = test::temp_file("run.json"), h5b = test::temp_file("again.h5"),
                          j2 = test::temp_file("again.json");
        write_record_file(j, w->record, w->summary, w->metrics);
        EXPECT_EQ(slurp(j), json);
        const RecordFile from_json = read_record_file(j);
        write_record_file(h5b, from_json.record, from_json.summary_json, from_json.metrics_json);
        const RecordFile back = read_record_file(h5b);
        write_record_file(j2, back.record, back.summary_json, back.metrics_json);
        EXPECT_EQ(slurp(j2), json);
        for (const std::string& f : {h5, j, h5b, j2}) std::remove(f.c_str());
    }
}

// Without candidates, the streamed file still reads as the JSON record of the same run, on 1 and 2
// threads: the same choice points, counts and plans, their candidate lists empty.
TEST(RecordFile, WithoutCandidatesTheStreamedFileIsTheJson) {
    const std::string json = record_to_text(bare().record, bare().summary, bare().metrics);
    const std::string h5 = test::temp_file("bare.h5");
    for (int threads : {1, 2}) {
        const RecordFile s = streamed(bare(), h5, threads);
        EXPECT_EQ(text_of(s), json) << threads << " threads";
        ASSERT_EQ(s.record.choices.size(), wandering().record.choices.size());
        for (std::size_t c = 0; c < s.record.choices.size(); ++c) {
            const ChoicePoint &got = s.record.choices[c], &with = wandering().record.choices[c];
            EXPECT_TRUE(got.candidates.empty());
            EXPECT_EQ(std::pair(got.taken, got.queries), std::pair(with.taken, with.queries)) << "choice " << c;
        }
    }
    std::remove(h5.c_str());
}

// Integer columns are narrower on disk than in memory (docs/formats.md); a value that does not fit its
// column is refused in one line naming the file and the column, never cut short.
TEST(RecordFile, AValueWiderThanItsColumnIsRefused) {
    Record r = wandering().record;
    r.choices[5].frame = std::int64_t(1) << 31;
    const std::string h5 = test::temp_file("wide.h5");
    try {
        write_record_file(h5, r, wandering().summary, wandering().metrics);
        ADD_FAILURE() << "written";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), h5 + ": /choices/frame: 2147483648 does not fit in 32 bits");
    }
    std::remove(h5.c_str());
}

TEST(RecordFile, TheRunsKeepWhatTheLayoutNeeds) {
    bool left = false, intended = false, queries = false;
    for (const AgentTrack& t : leaving().record.tracks) left = left || t.left_frame.has_value();
    for (const ChoicePoint& c : leaving().record.choices) intended = intended || !c.intended.empty();
    for (const ChoicePoint& c : wandering().record.choices)
        for (const Candidate& k : c.candidates) queries = queries || !k.against.empty();
    EXPECT_TRUE(left && intended && queries);
}

// A version 2 HDF5 record (fuzz/corpus-record/small.h5, an avoiding run written before the names of one
// meaning): its clips' "commit" column reads as the choice point that took each, its candidates' one flag
// "outside" as meets_solid - which is then just where a query met a wall.
TEST(RecordFile, Version2Hdf5ReadsInTodaysNames) {
    const Record r = read_record_file(std::string(MOBB_SOURCE_DIR) + "/fuzz/corpus-record/small.h5").record;
    ASSERT_EQ(r.select, "wander");
    int meets = 0;
    for (const ChoicePoint& cp : r.choices)
        for (const Candidate& k : cp.candidates) {
            bool solid_hit = false;
            for (const CandidateQuery& q : k.against) solid_hit = solid_hit || (q.agent < 0 && q.hit);
            EXPECT_EQ(k.meets_solid, solid_hit);
            EXPECT_FALSE(k.leaves_world);
            meets += k.meets_solid;
        }
    EXPECT_GT(meets, 0);
    int taken = 0;
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (const PlacedClip& c : r.tracks[a].clips) {
            if (c.choice < 0) continue;
            const ChoicePoint& cp = r.choices.at(std::size_t(c.choice));
            EXPECT_TRUE(cp.agent == int(a) && cp.frame == c.start && cp.taken == c.clip) << "choice " << c.choice;
            ++taken;
        }
    EXPECT_EQ(std::size_t(taken), r.choices.size());
}

TEST(RecordFile, TruncatedHdf5IsRefusedInOneLine) {
    const std::string h5 = test::temp_file("whole.h5"), cut = test::temp_file("cut.h5");
    write_record_file(h5, wandering().record, wandering().summary, wandering().metrics);
    const std::string bytes = slurp(h5);
    for (double keep : {0.0, 0.001, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999}) {
        std::ofstream(cut, std::ios::binary) << bytes.substr(0, std::size_t(double(bytes.size()) * keep));
        EXPECT_NE(read_error(cut), "") << "kept " << keep;
    }
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 1);
    EXPECT_NE(read_error(cut), "");
    for (const std::string& f : {h5, cut}) std::remove(f.c_str());
}

TEST(RecordFile, DamagedSamplesNameTheirBlock) {
    const std::string h5 = test::temp_file("damaged.h5");
    write_record_file(h5, wandering().record, wandering().summary, wandering().metrics);
    std::string bytes = slurp(h5);
    // One sample's x, found by its bytes (the samples are stored as native doubles), changed.
    const double x = wandering().record.tracks[3].samples[100][1];
    const std::size_t at = bytes.find(std::string(reinterpret_cast<const char*>(&x), sizeof x));
    ASSERT_NE(at, std::string::npos);
    bytes[at] = char(bytes[at] ^ 0x55);
    std::ofstream(h5, std::ios::binary) << bytes;
    const std::string e = read_error(h5);
    EXPECT_NE(e.find("/tracks/samples block"), std::string::npos) << e;
    std::remove(h5.c_str());
}

// MOBB_JSON_RECORD_MB set to `mb` megabytes for the life of the guard, then unset as the tests run.
struct JsonLimit {
    explicit JsonLimit(double mb) { ::setenv("MOBB_JSON_RECORD_MB", std::to_string(mb).c_str(), 1); }
    ~JsonLimit() { ::unsetenv("MOBB_JSON_RECORD_MB"); }
    JsonLimit(const JsonLimit&) = delete;
    JsonLimit& operator=(const JsonLimit&) = delete;
};

// The size a JSON record's text is estimated at, from its counts, is its size within a fifth.
TEST(RecordFile, AJsonRecordsSizeIsEstimatedFromItsCounts) {
    for (const Written* w : {&wandering(), &leaving(), &bare()}) {
        const double text = double(record_to_text(w->record, w->summary, w->metrics).size());
        const JsonRecordCounts n = json_record_counts(w->record);
        EXPECT_GT(n.samples, 0u);
        EXPECT_NEAR(double(json_record_bytes(n)) / text, 1.0, 0.2) << n.samples << " samples";
    }
    // A run's expected counts: every agent at every frame, and its choice points' candidates when kept.
    const JsonRecordCounts e = expected_json_record(10, 300, 100, "wander", true);
    EXPECT_EQ(std::tuple(e.samples, e.clips, e.choices), std::tuple(3000u, 110u, 100u));
    EXPECT_GT(expected_json_record(10, 300, 100, "random", true).candidates, e.candidates);
    EXPECT_EQ(expected_json_record(10, 300, 100, "wander", false).queries, 0u);
}

// A JSON record is held whole to be written and read: past the limit (MOBB_JSON_RECORD_MB, set small here)
// it is refused in one line naming the file, the memory it would need and the limit, before any of it is
// written or parsed; an HDF5 record, which streams, is not limited.
TEST(RecordFile, AJsonRecordPastTheLimitIsRefusedUpFront) {
    const Written& w = wandering();
    const std::string json = test::temp_file("limit.json"), h5 = test::temp_file("limit.h5");
    const double text_mb = double(record_to_text(w.record, w.summary, w.metrics).size()) / 1e6;
    std::remove(json.c_str());
    {
        const JsonLimit limit(text_mb * 2);  // under the memory writing takes, several times the text
        const std::string e = test::file_error(json, [&] { write_record_file(json, w.record, w.summary, w.metrics); });
        EXPECT_NE(e.find(": writing this JSON record"), std::string::npos) << e;
        EXPECT_NE(e.find("over the limit of"), std::string::npos) << e;
        EXPECT_NE(e.find("(MOBB_JSON_RECORD_MB); record to .h5 instead"), std::string::npos) << e;
        EXPECT_FALSE(std::ifstream(json).good());  // nothing written
        write_record_file(h5, w.record, w.summary, w.metrics);
        EXPECT_EQ(read_record_file(h5).record.choices.size(), w.record.choices.size());
    }
    write_record_file(json, w.record, w.summary, w.metrics);  // under the default limit (2 GB)
    {
        const JsonLimit limit(text_mb * 2);  // under the memory reading takes
        const std::string e = read_error(json);
        EXPECT_NE(e.find(": reading this JSON record ("), std::string::npos) << e;
        EXPECT_NE(e.find("mobb record convert " + json + " "), std::string::npos) << e;
        EXPECT_EQ(test::file_error(json, [&] { open_record(json); }), e);
    }
    {
        const JsonLimit limit(text_mb * 8);
        EXPECT_EQ(read_error(json), "");
    }
    ::setenv("MOBB_JSON_RECORD_MB", "lots", 1);
    EXPECT_THROW(json_record_limit(), std::runtime_error);
    ::unsetenv("MOBB_JSON_RECORD_MB");
    EXPECT_EQ(json_record_limit(), 2000000000u);
    std::remove(json.c_str());
    std::remove(h5.c_str());
}

TEST(RecordFile, OtherFilesAreRefusedInOneLine) {
    const std::string f = test::temp_file("text.h5");
    std::ofstream(f) << "{\"format\": \"mobb crowd record\"}";
    EXPECT_NE(read_error(f).find("not an HDF5 file"), std::string::npos);
    EXPECT_NE(read_error(test::temp_file("missing.h5")), "");
    std::remove(f.c_str());
}

}  // namespace
}  // namespace mobb::crowd
