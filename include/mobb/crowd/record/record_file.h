// Crowd record files, by extension: JSON (".json" and anything else; the layout in record.h) for small
// runs and tests, HDF5 (".h5", ".hdf5"; the layout in docs/formats.md) for large ones - chunked, written
// block by block and flushed after each, read by h5py. Both hold the same fields: a record converts
// either way (`mobb record convert`) and back to the same bytes.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mobb/crowd/record/record.h"

namespace mobb::crowd {

/// A record file's contents: the record, and its "summary" and "metrics" objects as JSON text (empty
/// when the file has none).
struct RecordFile {
    Record record;
    std::string summary_json, metrics_json;
    /// One line when the file is incomplete (its writing stopped: killed, a full disk) and was read up to
    /// its last mark: "FILE: incomplete ...: N of M frames"; empty for a finished file.
    std::string note;
};

/// Whether `file` names an HDF5 record (extension .h5 or .hdf5).
bool is_h5_record(const std::string& file);

/// Whether a run recorded to `file` keeps its choice points' candidates and their queries
/// (CrowdOptions::record_queries) unless told: a JSON record does (small runs, whose candidates the viewer
/// lists), an HDF5 one does not (large runs: candidates and queries are four fifths of its table rows, and
/// collecting them costs the run time; docs/formats.md).
bool keeps_candidates(const std::string& file);

// A JSON record is held whole: written at the end of its run from the whole record, as one document and
// one text, and read back as one document (nlohmann::json) - several times its text in memory. Past a
// limit it is refused up front, in one line naming the file, the memory it would need and the limit, and
// an HDF5 record (which streams; docs/crowd.md, "Records and memory") is the way. Streaming the JSON
// instead would not help: a record too large to hold is one the viewer and Python cannot read.

/// What a JSON record holds, counted in a record or expected of a run: the size of its text, and so the
/// memory to write or read it, follow from these (json_record_bytes).
struct JsonRecordCounts {
    std::uint64_t samples = 0;     ///< disks [t, x, y, r]: one per agent per frame it is in the run
    std::uint64_t clips = 0;       ///< placed clips: each agent's first, then one per choice point
    std::uint64_t choices = 0;     ///< choice points
    std::uint64_t candidates = 0;  ///< their candidates, when kept (CrowdOptions::record_queries)
    std::uint64_t queries = 0;     ///< the candidates' queries ("against")
};

/// Counted in a record.
JsonRecordCounts json_record_counts(const Record& record);

/// Expected of a run of `agents` x `frames` with `choices` choice points: with candidates kept, as many
/// candidates and queries per choice point as a run of selection mode `select` tests on average ("random"
/// tests every clip, some six times what the avoiding modes do).
JsonRecordCounts expected_json_record(std::uint64_t agents, std::int64_t frames, std::uint64_t choices,
                                      const std::string& select, bool candidates);

/// Bytes of a JSON record's text (about: the bytes each sample, clip, choice point, candidate and query
/// take in it).
std::uint64_t json_record_bytes(const JsonRecordCounts& counts);

/// The most memory (bytes) a JSON record may need to be written or read whole: MOBB_JSON_RECORD_MB
/// megabytes (1e6 bytes) when set, else 2 GB (2e9 bytes). Throws std::runtime_error for a value that is
/// not a positive number.
std::uint64_t json_record_limit();

/// Throws std::runtime_error "FILE: writing this JSON record (about T of text) would need about M of
/// memory, over the limit of L (MOBB_JSON_RECORD_MB); record to .h5 instead" when writing a record of
/// `counts` to `file` would need more than json_record_limit().
void check_json_record_write(const std::string& file, const JsonRecordCounts& counts);

/// Throws std::runtime_error "FILE: reading this JSON record (S) would need about M of memory, over the
/// limit of L (MOBB_JSON_RECORD_MB); ..." when reading JSON record `file`, of `file_bytes` bytes, would
/// need more than json_record_limit().
void check_json_record_read(const std::string& file, std::uint64_t file_bytes);

/// Reads a record file of either kind, every field checked as load_record says; an incomplete HDF5 file
/// (RecordFile::note) up to its last mark: its frames so far, the choice points and clips of those
/// frames; a JSON file past the limit is refused before it is parsed (check_json_record_read). Throws
/// std::runtime_error, one line naming the file and the place: "FILE: PLACE: message" (a JSON place like
/// tracks[2].samples[7][3], an HDF5 one like /choices/agent block 3).
RecordFile read_record_file(const std::string& file);

/// Writes the record to `file` (its kind by extension), replacing it. Throws std::runtime_error
/// "FILE: cannot write ..." when the file cannot be written (a disk full, a missing folder), and as
/// check_json_record_write does, before writing anything, for a JSON record past the limit.
void write_record_file(const std::string& file, const Record& record, const std::string& summary_json,
                       const std::string& metrics_json = "");

/// An HDF5 record written as the run goes (CrowdOptions::sink): the header and goals when the run begins,
/// each choice point (with the candidates and queries it holds) and each clip appended to the file's tables
/// as they are committed, a block (4,096 rows) at a time, and the samples a block of frames at a time as the
/// frames become final; the rest (the agents' left_frame, summary, metrics) by finish(). Between begin()
/// and finish() the file is written on a thread of its own, in the order of the calls: each call copies
/// what it sends and returns (it waits only while 8 blocks wait to be written). At least every 30 frames
/// the file is flushed and marked readable up to there (its "written" attribute, docs/formats.md): a
/// writer stopped before finish() (killed, a full disk) leaves a file that read_record_file reads up to
/// its last mark written, with a note. write_record_file uses it for a whole record too. Errors:
/// std::runtime_error "FILE: PLACE: ...", from the call that met them or, met on the writer's thread, from
/// the next call.
class H5RecordWriter : public RecordSink {
public:
    /// Creates (replaces) the file; `graph` and `scenario` name them in the header until the record
    /// given to begin() or finish() names its own.
    explicit H5RecordWriter(const std::string& file, const std::string& graph = "", const std::string& scenario = "");
    ~H5RecordWriter() override;
    bool keeps_commits() const override { return true; }
    void begin(const Record& header) override;
    void choice(std::size_t index, const ChoicePoint& choice) override;
    void clip(int agent, const PlacedClip& clip) override;
    void frames(const FrameBlock& block) override;
    /// Writes the rest of `record`: its header, left frames, summary and metrics; its choice points, if it
    /// holds any, must be those sent, and its frames those sent.
    void finish(const Record& record, const std::string& summary_json, const std::string& metrics_json);

private:
    struct Impl;  // the file and its tables (src/crowd/record/record_h5_write.cpp)
    std::unique_ptr<Impl> impl_;
};

/// Frames first .. last - 1 of a record, of agents agent_first .. agent_last - 1: their disks then, and
/// what the file says of the run.
struct SampleWindow {
    double dt = 0;            ///< seconds per frame
    std::int64_t frames = 0;  ///< the run's frames
    std::size_t agents = 0;   ///< the run's agents
    std::int64_t first = 0, last = 0;
    std::size_t agent_first = 0, agent_last = 0;
    /// (last - first) x width() disks [t, x, y, r] (seconds, metres): agent a at frame f is
    /// samples[(f - first) * width() + a - agent_first]; NaN from the frame it left the run on.
    std::vector<std::array<double, 4>> samples;
    std::string summary_json, metrics_json;
    std::string note;  ///< as RecordFile::note (frames: those the incomplete file holds)

    std::size_t width() const { return agent_last - agent_first; }
};

/// Reads frames first .. last - 1 (clamped to the run) of every agent of a record file: of an HDF5 file
/// only the header, the clips and those frames' blocks (a long run's window in the time it takes to
/// read the window; record_reader.h reads other parts); of a JSON file, the whole record (checked as
/// read_record_file does). Throws std::runtime_error as read_record_file does.
SampleWindow read_sample_window(const std::string& file, std::int64_t first, std::int64_t last);

}  // namespace mobb::crowd
