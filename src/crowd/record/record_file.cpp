// Record files by extension: JSON or HDF5 (include/mobb/crowd/record/record_file.h).
#include "mobb/crowd/record/record_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "record/record_json.h"

namespace mobb::crowd {

bool is_h5_record(const std::string& file) {
    const auto ends = [&](const std::string& e) {
        return file.size() > e.size() && file.compare(file.size() - e.size(), e.size(), e) == 0;
    };
    return ends(".h5") || ends(".hdf5");
}

bool keeps_candidates(const std::string& file) { return !is_h5_record(file); }

namespace {

// Bytes each item takes in a JSON record's text (record_json_write.cpp): a sample line of four doubles
// at full precision; a clip object; a choice point with its plan, without candidates; a candidate
// object; a query [agent, index, piece, mine, hit]. Fitted to runs' files (docs/crowd.md, "Records and
// memory").
constexpr double kSampleBytes = 71, kClipBytes = 216, kChoiceBytes = 458, kCandidateBytes = 165, kQueryBytes = 45;

// Candidates and queries per choice point, on average, where a run keeps them: random mode tests every
// candidate and runs all its queries; the avoiding modes stop a candidate at its first hit (wander's
// numbers, the larger, stand for goal mode too). Measured as above.
constexpr double kRandomCandidates = 28.5, kRandomQueries = 24.6, kWanderCandidates = 4.7, kWanderQueries = 8.6;

// Peak memory (bytes) per byte of a JSON record's text. Writing: the run with its whole record, the
// document (nlohmann::ordered_json: a node and an array per tuple of numbers) and the text; reading: the
// document and the record parsed from it. The largest measured, rounded up (docs/crowd.md).
constexpr double kWriteMemory = 7.5, kReadMemory = 4.5;

// The limit unless MOBB_JSON_RECORD_MB is set: 2 GB, what a recorded run may take. The same on every
// machine, so that a command that runs on one runs on another; a record written within it is read within
// it (kReadMemory < kWriteMemory); a larger one belongs in HDF5, which streams.
constexpr double kDefaultLimitBytes = 2e9;

// "480 MB", "2.03 GB", "2 GB", "0.05 MB": bytes in megabytes below a gigabyte, in gigabytes above.
std::string amount(double bytes) {
    const bool gb = bytes >= 1e9;
    const double x = bytes / (gb ? 1e9 : 1e6);
    std::ostringstream s;
    if (x >= 0.1) s << std::fixed << std::setprecision(x < 10 && x != std::round(x) ? 2 : 0);
    if (x < 0.1) s << std::setprecision(2);
    s << x << (gb ? " GB" : " MB");
    return s.str();
}

std::string over_limit(double memory, double limit) {
    return "would need about " + amount(memory) + " of memory, over the limit of " + amount(limit) +
           " (MOBB_JSON_RECORD_MB)";
}

}  // namespace

JsonRecordCounts json_record_counts(const Record& record) {
    JsonRecordCounts n;
    n.choices = record.choices.size();
    for (const AgentTrack& t : record.tracks) {
        n.samples += t.samples.size();
        n.clips += t.clips.size();
    }
    for (const ChoicePoint& c : record.choices) {
        n.candidates += c.candidates.size();
        for (const Candidate& k : c.candidates) n.queries += k.against.size();
    }
    return n;
}

JsonRecordCounts expected_json_record(std::uint64_t agents, std::int64_t frames, std::uint64_t choices,
                                      const std::string& select, bool candidates) {
    JsonRecordCounts n;
    n.samples = agents * std::uint64_t(std::max<std::int64_t>(frames, 0));
    n.clips = agents + choices;
    n.choices = choices;
    if (!candidates) return n;
    const bool random = select == "random";
    n.candidates = std::uint64_t(double(choices) * (random ? kRandomCandidates : kWanderCandidates));
    n.queries = std::uint64_t(double(choices) * (random ? kRandomQueries : kWanderQueries));
    return n;
}

std::uint64_t json_record_bytes(const JsonRecordCounts& counts) {
    const double bytes = double(counts.samples) * kSampleBytes + double(counts.clips) * kClipBytes +
                         double(counts.choices) * kChoiceBytes + double(counts.candidates) * kCandidateBytes +
                         double(counts.queries) * kQueryBytes;
    return std::uint64_t(bytes);
}

std::uint64_t json_record_limit() {
    const char* text = std::getenv("MOBB_JSON_RECORD_MB");
    if (!text) return std::uint64_t(kDefaultLimitBytes);
    char* end = nullptr;
    const double mb = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(mb) || mb <= 0 || mb > 1e12)
        throw std::runtime_error(std::string("MOBB_JSON_RECORD_MB: expected a positive number of megabytes, got \"") +
                                 text + "\"");
    return std::uint64_t(std::ceil(mb * 1e6));
}

void check_json_record_write(const std::string& file, const JsonRecordCounts& counts) {
    const double text = double(json_record_bytes(counts)), memory = text * kWriteMemory;
    const double limit = double(json_record_limit());
    if (memory <= limit) return;
    throw std::runtime_error(file + ": writing this JSON record (about " + amount(text) + " of text) " +
                             over_limit(memory, limit) + "; record to .h5 instead");
}

void check_json_record_read(const std::string& file, std::uint64_t file_bytes) {
    const double memory = double(file_bytes) * kReadMemory, limit = double(json_record_limit());
    if (memory <= limit) return;
    const std::string stem =
        file.size() > 5 && file.compare(file.size() - 5, 5, ".json") == 0 ? file.substr(0, file.size() - 5) : file;
    const auto mb = std::uint64_t(std::ceil(memory / 1e6));
    throw std::runtime_error(file + ": reading this JSON record (" + amount(double(file_bytes)) + ") " +
                             over_limit(memory, limit) +
                             "; convert it where memory allows (MOBB_JSON_RECORD_MB=" + std::to_string(mb) +
                             " mobb record convert " + file + " " + stem + ".h5) and read the .h5, or record to .h5");
}

RecordFile read_record_file(const std::string& file) {
    return is_h5_record(file) ? read_h5_record(file) : read_json_record(file);
}

Record load_record(const std::string& file) {
    RecordFile r = read_record_file(file);
    if (!r.note.empty()) std::cerr << r.note << "\n";
    return std::move(r.record);
}

void write_record_file(const std::string& file, const Record& record, const std::string& summary_json,
                       const std::string& metrics_json) {
    if (is_h5_record(file)) return write_h5_record(file, record, summary_json, metrics_json);
    check_json_record_write(file, json_record_counts(record));
    const std::string text = record_to_text(record, summary_json, metrics_json);
    std::ofstream f(file, std::ios::binary);
    f << text;
    f.flush();
    if (!f) throw std::runtime_error(file + ": cannot write");
}

}  // namespace mobb::crowd
