// The JSON layout of a crowd record (include/mobb/crowd/record/record.h), shared by the record files: JSON
// (record_json_read.cpp, record_json_write.cpp) and HDF5 (record_h5_read.cpp), which checks what it reads
// through the same reader.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "mobb/crowd/record/record_file.h"

namespace mobb::crowd {

/// The record of a JSON document in the layout of record.h, every field checked as load_record says.
/// Throws std::runtime_error "FILE: PLACE: message".
Record record_from_json(const nlohmann::ordered_json& j, const std::string& file);

/// The record as a JSON document; `summary` and `metrics` (JSON objects as text) inserted as given.
nlohmann::ordered_json record_json(const Record& r, const std::string& summary_json, const std::string& metrics_json);

/// The "summary" of a record document as text; a version 1 or 2 record's under this version's names
/// ("fallbacks_outside_world" counted fallbacks meeting a wall or an obstacle).
std::string stored_summary(const nlohmann::ordered_json& j);

/// "place[k]": element k of the array at `place`, as errors name it.
std::string element_place(const std::string& place, std::size_t k);

/// A field of a record out of its range: "PLACE: message" (the reader puts the file in front).
struct FieldError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The header of a record document - format, version, graph, dt, frames, world and obstacles, seed,
/// tree, select, scenario - checked as record_from_json checks it; no tracks, no choice points.
/// Throws std::runtime_error "FILE: PLACE: message".
Record record_header_from_json(const nlohmann::ordered_json& j, const std::string& file);

/// Choice point `row` of a record (a "choices" element of the layout, in today's names), checked as
/// record_from_json checks it against `header` (its tracks: the agents) with `row` choice points before
/// it; places named choices[row]. Throws std::runtime_error "FILE: PLACE: message".
ChoicePoint choice_from_json(const nlohmann::ordered_json& c, const Record& header, std::size_t row,
                             const std::string& file);

/// check_graph_clips for one choice point, row `row` of its record, whose graph `graph` has `clips` clips.
void check_choice_clips(const ChoicePoint& cp, std::size_t row, std::size_t clips, const std::string& graph);

// The checks of single values, in the JSON reader's words, for readers that take values from elsewhere
// (record_h5_window.cpp). Each throws FieldError "PLACE: message"; `place` is made only then.
using Place = std::function<std::string()>;
/// A position within 1000 km of the origin (metres).
void check_coordinate(double x, const Place& place);
/// A character's radius: 0 to 10 m.
void check_radius(double r, const Place& place);
/// Time t of global frame `frame` (t = frame * dt), up to `slack` relative.
void check_frame_time(double t, std::int64_t frame, double dt, double slack, const Place& place);
/// Finite.
void check_finite(double x, const Place& place);
/// Whether disk [t, x, y, r] of global frame `frame` passes check_frame_time (slack 1e-9),
/// check_coordinate and check_radius: a reader of many disks runs those for their message only when not.
bool disk_ok(const std::array<double, 4>& d, std::int64_t frame, double dt);

/// Reads a JSON record file (record_from_json) with its summary and metrics.
RecordFile read_json_record(const std::string& file);

/// Reads an HDF5 record file (record_h5_read.cpp); writes one (record_h5_write.cpp).
RecordFile read_h5_record(const std::string& file);
void write_h5_record(const std::string& file, const Record& r, const std::string& summary_json,
                     const std::string& metrics_json);

}  // namespace mobb::crowd
