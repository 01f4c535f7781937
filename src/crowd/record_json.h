// The JSON layout of a crowd record (include/mobb/crowd/record.h), shared by the record files: JSON
// (record_json_read.cpp, record_json_write.cpp) and HDF5 (record_h5_read.cpp), which checks what it reads
// through the same reader.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "mobb/crowd/record_file.h"

namespace mobb::crowd {

/// The record of a JSON document in the layout of record.h, every field checked as load_record says.
/// Throws std::runtime_error "FILE: PLACE: message".
Record record_from_json(const nlohmann::ordered_json& j, const std::string& file);

/// The record as a JSON document; `summary` and `metrics` (JSON objects as text) inserted as given.
nlohmann::ordered_json record_json(const Record& r, const std::string& summary_json, const std::string& metrics_json);

/// The "summary" of a record document as text; a version 1 or 2 record's under this version's names
/// ("fallbacks_outside_world" counted fallbacks meeting a wall or an obstacle).
std::string stored_summary(const nlohmann::ordered_json& j);

/// Reads a JSON record file (record_from_json) with its summary and metrics.
RecordFile read_json_record(const std::string& file);

/// Reads an HDF5 record file (record_h5_read.cpp); writes one (record_h5_write.cpp).
RecordFile read_h5_record(const std::string& file);
SampleWindow read_h5_window(const std::string& file, std::int64_t first, std::int64_t last);
void write_h5_record(const std::string& file, const Record& r, const std::string& summary_json,
                     const std::string& metrics_json);

}  // namespace mobb::crowd
