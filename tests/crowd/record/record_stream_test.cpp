// Streamed runs (CrowdOptions::sink): the metrics and the contact check computed on the frames as they
// come equal those of the whole record, to the last bit, whether agents avoid each other or not (random
// mode touches); a writer stopped before finish() leaves a file read up to its last mark, with a note.
// (The streamed file against the JSON record, field by field: record_file_test.cpp.)
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include "files.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/record/record_file.h"
#include "mobb/crowd/sim/crowd.h"
#include "record_parts.h"
#include "record_runs.h"

namespace mobb::crowd {
namespace {

using test::temp_file;

const MotionGraph& graph() { return test::committed_graph(); }

// The metrics of a run on `g`, streamed and on the whole record, bit for bit; what they covered.
void expect_stream_equals_whole(const MotionGraph& g, bool& contacts, bool& reached, bool& left) {
    for (const CrowdOptions& o : {test::random_mode_crowd(), test::crowd_beside_obstacle(10), test::leaving_crowd()}) {
        const CrowdRun whole = run_crowd(g, NarrowPhase::sweep(g), o);
        const CrowdMetrics expected = crowd_metrics(whole.record, g, o.goal_radius);
        CrowdOptions s = o;
        RecordSink nowhere;
        s.sink = &nowhere;
        const CrowdRun run = run_crowd(g, NarrowPhase::sweep(g), s);
        ASSERT_TRUE(run.metrics.has_value());
        const CrowdMetrics& m = *run.metrics;
        EXPECT_EQ(metrics_json(m), metrics_json(expected));
        EXPECT_EQ(summary_json(run.summary), summary_json(whole.summary));
        // Bit for bit, beyond the JSON's rounding.
        for (const auto field :
             {&CrowdMetrics::max_penetration, &CrowdMetrics::mean_speed, &CrowdMetrics::idle_share,
              &CrowdMetrics::longest_idle, &CrowdMetrics::path_ratio, &CrowdMetrics::time_ratio,
              &CrowdMetrics::mean_time_to_goal, &CrowdMetrics::composite01, &CrowdMetrics::composite02})
            EXPECT_EQ(m.*field, expected.*field);
        contacts = contacts || (m.contacts > 0 && m.max_penetration > 1e-3 && m.contacts_outside_fallbacks > 0);
        reached = reached || m.reached > 0;
        left = left || m.left > 0;
    }
}

TEST(RecordStream, MetricsOnTheStreamEqualTheWholeRecords) {
    bool contacts = false, reached = false, left = false;
    expect_stream_equals_whole(graph(), contacts, reached, left);
    EXPECT_TRUE(contacts && reached && left);  // the runs cover what the metrics count
}

// With disks centred on the body the motion metrics follow the root (metrics_test.cpp): the stream places
// the roots as the whole record's clips do.
TEST(RecordStream, MetricsOnTheStreamFollowTheRootAsTheWholeRecords) {
    bool contacts = false, reached = false, left = false;
    expect_stream_equals_whole(test::body_centred_graph(), contacts, reached, left);
    EXPECT_TRUE(contacts && reached && left);
}

// The stream checks a window of frames at a time, the pairs found by columns of a grid shared among the
// workers: a crowd wide enough for several tasks, whose run does not end on a window's edge, on three
// threads finds the contacts the whole record's frame-by-frame check finds.
TEST(RecordStream, ContactsOnTheStreamOnThreadsEqualTheWholeRecords) {
    CrowdOptions o = test::random_mode_crowd();
    o.agents = 800;
    o.world.x1 = o.world.y1 = 200;
    o.seconds = 4.1;
    o.threads = 3;
    const MotionGraph& g = graph();
    const CrowdRun whole = run_crowd(g, NarrowPhase::sweep(g), o);
    const std::vector<Contact> expected = frame_contacts(whole.record);
    RecordSink nowhere;
    o.sink = &nowhere;
    const CrowdRun run = run_crowd(g, NarrowPhase::sweep(g), o);
    ASSERT_GT(expected.size(), 100u);
    EXPECT_EQ(run.summary.contacts, expected.size());
    EXPECT_EQ(metrics_json(*run.metrics), metrics_json(crowd_metrics(whole.record, g, o.goal_radius)));
    EXPECT_EQ(run.metrics->max_penetration, crowd_metrics(whole.record, g, o.goal_radius).max_penetration);
}

// Forwards to a writer, and stops the run (as a kill would) at the block of frames starting at `stop`.
class Stopping : public RecordSink {
public:
    Stopping(H5RecordWriter& out, std::int64_t stop) : out_(out), stop_(stop) {}
    bool keeps_commits() const override { return true; }
    void begin(const Record& header) override { out_.begin(header); }
    void choice(std::size_t index, const ChoicePoint& choice) override { out_.choice(index, choice); }
    void clip(int agent, const PlacedClip& clip) override { out_.clip(agent, clip); }
    void frames(const FrameBlock& block) override {
        if (block.first >= stop_) throw std::runtime_error("stopped");
        out_.frames(block);
    }

private:
    H5RecordWriter& out_;
    std::int64_t stop_;
};

// The whole record cut to its first `frames` frames: what a file stopped there holds.
Record cut(Record r, std::int64_t frames) {
    r.frames = frames;
    for (AgentTrack& t : r.tracks) {
        if (std::int64_t(t.samples.size()) > frames) t.samples.resize(std::size_t(frames));
        if (t.left_frame && *t.left_frame >= frames) t.left_frame.reset();
        while (!t.clips.empty() && t.clips.back().start >= frames) t.clips.pop_back();
    }
    while (!r.choices.empty() && r.choices.back().frame >= frames) r.choices.pop_back();
    return r;
}

TEST(RecordStream, AStoppedWriterLeavesItsFramesUpToTheLastMark) {
    const CrowdOptions o = test::leaving_crowd();
    const CrowdRun whole = run_crowd(graph(), NarrowPhase::sweep(graph()), o);
    const std::int64_t block = std::min<std::int64_t>(256, 65536 / std::int64_t(whole.record.tracks.size()));
    const std::int64_t held = 2 * block;  // two blocks out, each marked (more than 30 frames)
    ASSERT_GT(whole.record.frames, held);
    const std::string file = temp_file("stopped.h5");
    {
        H5RecordWriter out(file, "graph.json");
        Stopping stopping(out, held);
        CrowdOptions s = o;
        s.sink = &stopping;
        EXPECT_THROW(run_crowd(graph(), NarrowPhase::sweep(graph()), s), std::runtime_error);
    }  // the writer goes without finish()
    const RecordFile r = read_record_file(file);
    EXPECT_NE(r.note.find(file + ": incomplete"), std::string::npos) << r.note;
    EXPECT_NE(r.note.find(" (" + std::to_string(held) + " of the run's "), std::string::npos) << r.note;
    EXPECT_EQ(r.note.find('\n'), std::string::npos);
    Record expected = cut(whole.record, held);
    expected.graph = "graph.json";
    EXPECT_EQ(record_to_text(r.record, r.summary_json, r.metrics_json), record_to_text(expected, "{}"));
    bool left = false;
    for (const AgentTrack& t : expected.tracks) left = left || t.left_frame.has_value();
    EXPECT_TRUE(left);  // the frames held see agents leave (the reader finds them by their NaN)
    const SampleWindow w = read_sample_window(file, 0, 1000000);
    EXPECT_EQ(w.frames, held);
    EXPECT_EQ(w.last, held);
    EXPECT_EQ(w.note, r.note);
    // Read in parts (record_reader.h), the same frames and choice points.
    const auto parts = open_record(file);
    EXPECT_EQ(parts->info().note, r.note);
    EXPECT_EQ(record_to_text(test::record_from_parts(*parts), parts->info().summary_json),
              record_to_text(expected, "{}"));
    std::remove(file.c_str());
}

TEST(RecordStream, AWriterStoppedBeforeItsFirstMarkIsRefusedInOneLine) {
    const std::string file = temp_file("empty.h5");
    { H5RecordWriter out(file); }
    try {
        read_record_file(file);
        ADD_FAILURE() << "read";
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind(file + ": incomplete", 0), 0u) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos);
    }
    std::remove(file.c_str());
}

}  // namespace
}  // namespace mobb::crowd
