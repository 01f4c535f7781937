// Records read in parts (record_reader.h): an HDF5 record's parts put together are the record read whole,
// every field; a window of frames, of agents, of choice points is that window of the whole record; only
// the blocks of a window are read, each once while the cache holds it; a damaged block is named when a
// window reaches it, a truncated file when it opens, in one line naming the file, never a crash.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <stdexcept>

#include <gtest/gtest.h>

#include "files.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/record/record_file.h"
#include "mobb/crowd/record/record_reader.h"
#include "mobb/crowd/sim/crowd.h"
#include "record_parts.h"
#include "record_runs.h"

namespace mobb::crowd {
namespace {

using test::record_from_parts;
using test::same_disks;
using test::slurp;
using test::temp_file;

using Written = test::WrittenRun;

// 60 agents, 10 s: two blocks of frames (256 and 44), right of way (reroutes), escapes.
const Written& dense() {
    static const Written r = [] {
        CrowdOptions o;
        o.agents = 60;
        o.seconds = 10;
        o.seed = 2;
        o.world.x1 = 13;
        o.world.y1 = 15;
        return test::run_written(o);
    }();
    return r;
}

// Frames per block of the samples (frame_stream.h: about 64 k disks, at most 256 frames).
std::int64_t block_of(const Record& r) { return std::min<std::int64_t>(256, 65536 / std::int64_t(r.tracks.size())); }

// Goal agents that leave at their goals (left frames, NaN samples, goals, intended clips).
const Written& leaving() {
    static const Written r = test::run_written(test::leaving_crowd(), test::fan_in_exit_name());
    return r;
}

// Random choice: contacts; and every 50th choice point marked a fallback (today's crowds take none).
const Written& touching() {
    static const Written r = [] {
        Written out = test::run_written(test::random_mode_crowd());
        for (std::size_t k = 0; k < out.record.choices.size(); k += 50) {
            out.record.choices[k].fallback = true;
            out.record.choices[k].outcome = "fallback";
        }
        return out;
    }();
    return r;
}

// The run written to `file` (its kind by extension).
std::string written(const Written& r, const std::string& name) {
    const std::string file = temp_file(name);
    write_record_file(file, r.record, r.summary, r.metrics);
    return file;
}

TEST(RecordReader, ThePartsPutTogetherAreTheWholeRecord) {
    bool reroutes = false, left = false;
    for (const Written* r : {&dense(), &leaving(), &touching()}) {
        const std::string json = record_to_text(r->record, r->summary, r->metrics);
        for (const char* name : {"whole.h5", "whole.json"}) {
            const std::string file = written(*r, name);
            const auto reader = open_record(file);
            EXPECT_EQ(reader->lazy(), is_h5_record(file));
            EXPECT_EQ(
                record_to_text(record_from_parts(*reader), reader->info().summary_json, reader->info().metrics_json),
                json)
                << file;
            EXPECT_TRUE(reader->header().choices.empty());
            for (const AgentTrack& t : reader->header().tracks) EXPECT_TRUE(t.samples.empty());
            std::remove(file.c_str());
        }
        for (const ChoicePoint& c : r->record.choices) reroutes = reroutes || !c.reroutes.empty();
        for (const AgentTrack& t : r->record.tracks) left = left || t.left_frame.has_value();
    }
    EXPECT_TRUE(reroutes && left);  // the runs hold what the layout has
}

// A record recorded without candidates (an HDF5 one unless asked) says so, and its choice points read in
// parts as they read whole: every list empty, nothing else missing.
TEST(RecordReader, ARecordWithoutCandidatesSaysSo) {
    Written bare = dense();
    const auto tested = std::find_if(bare.record.choices.begin(), bare.record.choices.end(),
                                     [](const ChoicePoint& c) { return !c.candidates.empty(); });
    ASSERT_NE(tested, bare.record.choices.end());
    const std::size_t row = std::size_t(tested - bare.record.choices.begin());
    for (ChoicePoint& c : bare.record.choices) c.candidates.clear();
    for (const char* name : {"bare.h5", "bare.json"}) {
        for (const Written* r : std::initializer_list<const Written*>{&dense(), &bare}) {
            const std::string file = written(*r, name);
            const auto reader = open_record(file);
            EXPECT_EQ(reader->has_candidates(), r != &bare) << file;
            const ChoicePoint c = reader->choice(row);
            EXPECT_EQ(c.candidates.size(), r->record.choices[row].candidates.size()) << file;
            EXPECT_EQ(c.queries, r->record.choices[row].queries) << file;  // its counts kept
            const auto summaries = reader->summaries(0, reader->choice_count());
            ASSERT_EQ(summaries.size(), r->record.choices.size());
            for (std::size_t k = 0; k < summaries.size(); ++k)
                EXPECT_EQ(summaries[k].candidates, r->record.choices[k].candidates.size()) << file << " " << k;
            std::remove(file.c_str());
        }
    }
}

// A window read from the file equals the same window cut from the record read whole: samples (of all
// agents, or a range), the rows of the choice points of those frames, their summaries, the contacts.
TEST(RecordReader, AWindowIsThatWindowOfTheWholeRecord) {
    for (const Written* r : {&dense(), &leaving(), &touching()}) {
        const Record& whole = r->record;
        const std::string file = written(*r, "window.h5");
        const auto reader = open_record(file);
        const std::int64_t n = whole.frames;
        const std::size_t agents = whole.tracks.size();
        for (const auto& [f0, f1] : std::vector<std::pair<std::int64_t, std::int64_t>>{
                 {0, 1}, {0, n}, {n / 3, n / 3 + 45}, {n - 7, n + 50}, {n / 2, n / 2}, {-5, 3}}) {
            for (const AgentRange range :
                 {AgentRange{}, AgentRange{1, agents / 2}, AgentRange{agents - 1, agents + 9}}) {
                const SampleWindow w = reader->samples(f0, f1, range);
                EXPECT_TRUE(same_disks(w, window_of(whole, f0, f1, range))) << f0 << " to " << f1;
                EXPECT_EQ(w.frames, n);
                EXPECT_EQ(w.agents, agents);
            }
            const auto [lo, hi] = reader->choice_rows(f0, f1);
            std::size_t want_lo = 0, want_hi = 0;
            for (const ChoicePoint& c : whole.choices) want_lo += c.frame < f0, want_hi += c.frame < f1;
            EXPECT_EQ(lo, want_lo);
            EXPECT_EQ(hi, std::max(want_lo, want_hi));
            for (const int agent : {-1, 0, 3}) {
                const std::vector<ChoiceSummary> s = reader->summaries(lo, hi, agent);
                std::size_t k = 0;
                for (std::size_t row = lo; row < hi; ++row) {
                    const ChoicePoint& c = whole.choices[row];
                    if (agent >= 0 && c.agent != agent) continue;
                    ASSERT_LT(k, s.size());
                    const ChoicePoint& p = s[k].point;
                    EXPECT_EQ(s[k].row, row);
                    EXPECT_EQ(s[k].candidates, c.candidates.size());
                    EXPECT_TRUE(p.agent == c.agent && p.frame == c.frame && p.taken == c.taken &&
                                p.outcome == c.outcome && p.fallback == c.fallback && p.queries == c.queries &&
                                p.tests2d == c.tests2d && p.tests3d == c.tests3d && p.samples == c.samples &&
                                p.pruned == c.pruned && p.holds == c.holds && p.hold == c.hold &&
                                p.hold_frame == c.hold_frame)
                        << "row " << row;
                    EXPECT_TRUE(p.candidates.empty() && p.escape.empty() && p.reroutes.empty());
                    ++k;
                }
                EXPECT_EQ(k, s.size());
            }
            // The contacts of the window's frames, as the frame check finds them on the whole record.
            std::vector<Contact> expected;
            for (const Contact& c : frame_contacts(whole))
                if (c.frame >= std::max<std::int64_t>(f0, 0) && c.frame < std::min(f1, n)) expected.push_back(c);
            const std::vector<Contact> got = frame_contacts(reader->samples(f0, f1), reader->header());
            ASSERT_EQ(got.size(), expected.size());
            for (std::size_t k = 0; k < got.size(); ++k)
                EXPECT_TRUE(got[k].frame == expected[k].frame && got[k].a == expected[k].a &&
                            got[k].b == expected[k].b && got[k].excused == expected[k].excused);
        }
        std::vector<ChoiceMark> fallbacks;
        for (std::size_t k = 0; k < whole.choices.size(); ++k)
            if (whole.choices[k].fallback) fallbacks.push_back({k, whole.choices[k].agent, whole.choices[k].frame});
        const std::vector<ChoiceMark> got = reader->fallbacks();
        ASSERT_EQ(got.size(), fallbacks.size());
        for (std::size_t k = 0; k < got.size(); ++k)
            EXPECT_TRUE(got[k].row == fallbacks[k].row && got[k].agent == fallbacks[k].agent &&
                        got[k].frame == fallbacks[k].frame);
        EXPECT_THROW(reader->choice(whole.choices.size()), std::out_of_range);
        std::remove(file.c_str());
    }
    EXPECT_FALSE(frame_contacts(touching().record).empty());
    bool fallback = false;
    for (const ChoicePoint& c : touching().record.choices) fallback = fallback || c.fallback;
    EXPECT_TRUE(fallback);
}

// Opening reads no samples; a window reads the blocks it spans, once while the cache holds them; a
// cache of one block reads a block again after another was read.
TEST(RecordReader, OnlyTheBlocksOfAWindowAreRead) {
    const std::string file = written(dense(), "blocks.h5");
    const std::int64_t block = block_of(dense().record), frames = dense().record.frames;
    ASSERT_GT(frames, block + 40);
    const auto reader = open_record(file);
    EXPECT_EQ(reader->counts().frames, 0);
    reader->samples(block + 10, block + 40);
    EXPECT_EQ(reader->counts().frames, frames - block);  // block 1 alone
    reader->samples(block + 20, block + 30);
    EXPECT_EQ(reader->counts().frames, frames - block);
    EXPECT_EQ(reader->counts().cached, 10);
    reader->samples(block - 5, block + 5);  // block 0 read, block 1 from the cache
    EXPECT_EQ(reader->counts().frames, frames);
    EXPECT_EQ(reader->counts().cached, 15);
    const auto one =
        open_record(file, dense().record.tracks.size() * std::size_t(block) * sizeof(std::array<double, 4>));
    one->samples(0, 5);
    one->samples(block, block + 5);
    one->samples(0, 5);
    EXPECT_EQ(one->counts().frames, block + (frames - block) + block);
    EXPECT_EQ(one->counts().cached, 0);
    // A choice point reads its own rows: the reader counts it, and nothing else of the samples.
    one->choice(dense().record.choices.size() / 2);
    EXPECT_EQ(one->counts().choices, 1);
    EXPECT_EQ(one->counts().frames, frames + block);
    std::remove(file.c_str());
}

// Damage in one block of samples: the file opens, windows elsewhere read, a window over the block names
// it; a field out of range names the same place as the whole reader does.
TEST(RecordReader, ADamagedBlockIsNamedWhenAWindowReachesIt) {
    const std::string file = written(dense(), "damaged.h5");
    std::string bytes = slurp(file);
    const std::int64_t block = block_of(dense().record), frame = block + 5;
    const double x = dense().record.tracks[7].samples[std::size_t(frame)][1];
    const std::size_t at = bytes.find(std::string(reinterpret_cast<const char*>(&x), sizeof x));
    ASSERT_NE(at, std::string::npos);
    bytes[at] = char(bytes[at] ^ 0x55);
    std::ofstream(file, std::ios::binary) << bytes;
    const auto reader = open_record(file);
    EXPECT_NO_THROW(reader->samples(0, block));
    const std::string e = test::file_error(file, [&] { reader->samples(frame - 1, frame + 1); });
    EXPECT_NE(e.find("/tracks/samples block 1: cannot read (truncated or corrupt)"), std::string::npos) << e;
    std::remove(file.c_str());

    // A sample out of range is named when a window reaches it, a clip out of order when the clip table
    // is read, as the whole reader names them.
    for (const bool clip : {false, true}) {
        Record bad = leaving().record;
        if (clip)
            bad.tracks[4].clips[1].start = bad.tracks[4].clips[0].start;
        else
            bad.tracks[2].samples[40][3] = -0.5;
        const std::string f = temp_file("bad.h5");
        write_record_file(f, bad, leaving().summary);
        const std::string whole = test::file_error(f, [&] { read_record_file(f); });
        const std::string parts = test::file_error(f, [&] {
            const auto parts_reader = open_record(f);
            parts_reader->samples(0, 100);
            parts_reader->header();  // the clip table
        });
        EXPECT_EQ(parts, whole);
        EXPECT_NE(whole.find(clip ? "tracks[4].clips[1].start" : "tracks[2].samples[40][3]"), std::string::npos)
            << whole;
        if (!clip) {
            EXPECT_NO_THROW(open_record(f)->samples(bad.frames - 10, bad.frames));  // another block reads
        }
        std::remove(f.c_str());
    }
}

TEST(RecordReader, ATruncatedFileIsRefusedInOneLine) {
    const std::string file = written(leaving(), "cut_whole.h5"), cut = temp_file("cut.h5");
    const std::string bytes = slurp(file);
    for (double keep : {0.0, 0.001, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999}) {
        std::ofstream(cut, std::ios::binary) << bytes.substr(0, std::size_t(double(bytes.size()) * keep));
        EXPECT_NE(test::file_error(cut, [&] { open_record(cut); }), "") << "kept " << keep;
    }
    for (const std::string& f : {file, cut}) std::remove(f.c_str());
}

// A version 2 file (fuzz/corpus-record/small.h5) reads in parts as it reads whole: today's names.
TEST(RecordReader, AVersion2FileReadsAsItReadsWhole) {
    const std::string file = std::string(MOBB_SOURCE_DIR) + "/fuzz/corpus-record/small.h5";
    const RecordFile whole = read_record_file(file);
    const auto reader = open_record(file);
    EXPECT_EQ(record_to_text(record_from_parts(*reader), reader->info().summary_json, reader->info().metrics_json),
              record_to_text(whole.record, whole.summary_json, whole.metrics_json));
}

}  // namespace
}  // namespace mobb::crowd
