// Reading a crowd record a part at a time, so that a record too large to hold opens in seconds: its
// header, goals and clips when opened; a window of frames (every agent's disks then) and the choice
// points when asked. An HDF5 record (record_file.h, the layout in docs/formats.md) is read so, from its
// chunks (src/crowd/record/record_h5_window.cpp); a JSON one is read whole when opened and answered from memory.
// The viewer (`mobb view --crowd`) and Python (`mobb.open_record`) read records through it.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mobb/crowd/record/record.h"
#include "mobb/crowd/record/record_file.h"

namespace mobb::crowd {

/// Agents first .. last - 1 of a record (clamped to it; all by default).
struct AgentRange {
    std::size_t first = 0, last = std::numeric_limits<std::size_t>::max();
};

/// A choice point of the record's table (its row, the index Record::choices, PlacedClip::choice and a
/// query's index name) without its candidates and plan, and how many candidates it tested.
struct ChoiceSummary {
    std::size_t row = 0;
    ChoicePoint point;  ///< candidates, escape, intended and reroutes left empty
    std::size_t candidates = 0;
};

/// Where a fallback was taken: the timeline's marks.
struct ChoiceMark {
    std::size_t row = 0;
    int agent = 0;
    std::int64_t frame = 0;
};

/// What a reader has taken from its file so far: what the viewer's test of a lazy open counts.
struct ReadCounts {
    std::int64_t frames = 0;      ///< frames of samples read from the file (whole blocks; a JSON record: all)
    std::int64_t cached = 0;      ///< frames of samples served from the cache instead
    std::int64_t choices = 0;     ///< choice points read with their candidates and plans (choice())
    std::int64_t table_rows = 0;  ///< rows of the choice table read (summaries(), fallbacks())
};

/// A record file opened for reading in parts. Not thread-safe. Errors (a damaged block, a field out of
/// range) throw std::runtime_error in one line naming the file and the place, as read_record_file does
/// ("r.h5: /tracks/samples block 3: cannot read (truncated or corrupt)"); the place of a choice point
/// is named as in the JSON layout with its row (choices[1234].candidates[2].hits).
class RecordReader {
public:
    virtual ~RecordReader() = default;
    /// Everything but the samples and the choice points, checked as load_record checks it: the run's
    /// header, the world, and every track's goals, at_goal, left_frame and clips (the whole clip table:
    /// about one clip per agent per second, small beside the samples; read on the first call, so that
    /// reading samples alone does not). Its tracks' samples and its choices are empty.
    virtual const Record& header() = 0;
    /// The record's summary and metrics (JSON objects as text; empty when the file has none), and the
    /// note of an incomplete file (RecordFile::note; its frames and choice points are those up to its
    /// last mark).
    virtual const RecordFile& info() const = 0;
    /// Choice points in the record: rows 0 .. choice_count() - 1, in frame order.
    virtual std::size_t choice_count() const = 0;
    /// True when parts are read from the file as asked (HDF5); false for a record held whole (JSON).
    virtual bool lazy() const = 0;
    /// Whether any choice point holds candidates. A run recorded without them (an HDF5 record unless
    /// `mobb crowd --record-candidates`; CrowdOptions::record_queries) holds none: every choice point's
    /// list is empty, which says nothing of how many the crowd tested.
    virtual bool has_candidates() const = 0;

    /// Frames first .. last - 1 (clamped to the record) of agents `agents`, each sample checked as
    /// load_record checks it. Frames come from a cache of recent blocks of frames when held there.
    virtual SampleWindow samples(std::int64_t first, std::int64_t last, AgentRange agents = {}) = 0;
    /// Rows [first, last) of the choice table: the choice points at frames `first_frame` .. `last_frame`
    /// - 1 (the table is in frame order).
    virtual std::pair<std::size_t, std::size_t> choice_rows(std::int64_t first_frame, std::int64_t last_frame) = 0;
    /// Rows first .. last - 1 (clamped) of the choice table, without candidates and plans; only those of
    /// agent `agent` when it is not negative.
    virtual std::vector<ChoiceSummary> summaries(std::size_t first, std::size_t last, int agent = -1) = 0;
    /// Choice point `row` whole: its candidates with their queries, and its plan. Throws
    /// std::out_of_range for a row past choice_count().
    virtual ChoicePoint choice(std::size_t row) = 0;
    /// Every choice point that took a fallback, in row order.
    virtual std::vector<ChoiceMark> fallbacks() = 0;
    virtual ReadCounts counts() const = 0;
    /// Checks the record's clip ids against a graph of `clips` clips as check_graph_clips does (throws
    /// std::runtime_error "PLACE: clip N is not in the graph ..."): the header's clips now and, of a
    /// record read in parts, each choice point's as choice() reads it.
    virtual void check_graph_clips(std::size_t clips) = 0;
};

/// Bytes of samples an HDF5 reader keeps of blocks it read, so that moving a window back and forth reads
/// each block once: 256 MB, a 10 s window of 26,000 agents at 30 fps.
constexpr std::size_t kRecordCacheBytes = std::size_t(256) << 20;

/// Opens a record file: an HDF5 one lazily (its header, goals and left frames now), a JSON one whole.
/// Throws std::runtime_error naming the file and the place, as read_record_file does.
std::unique_ptr<RecordReader> open_record(const std::string& file, std::size_t cache_bytes = kRecordCacheBytes);

/// Frames first .. last - 1 of agents `agents` of a whole record: what an HDF5 reader gives for the same
/// window of the same run (samples NaN from the frame an agent left on).
SampleWindow window_of(const Record& record, std::int64_t first, std::int64_t last, AgentRange agents = {});

/// The contacts at the window's frames (frame_contacts' order and test, on every agent of the window);
/// `header` gives the clips that excuse them (Contact::excused).
std::vector<Contact> frame_contacts(const SampleWindow& window, const Record& header);

/// Disk [t, x, y, r] of agent `agent` at frame `frame` of the window; null outside the window or when
/// the agent was no longer in the run then (NaN).
const std::array<double, 4>* window_disk(const SampleWindow& window, std::size_t agent, std::int64_t frame);

}  // namespace mobb::crowd
