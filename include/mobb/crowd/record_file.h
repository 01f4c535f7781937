// Crowd record files, by extension: JSON (".json" and anything else; the layout in record.h) for small
// runs and tests, HDF5 (".h5", ".hdf5"; the layout in docs/formats.md) for large ones - chunked, written
// block by block and flushed after each, read by h5py. Both hold the same fields: a record converts
// either way (`mobb record convert`) and back to the same bytes.
#pragma once
#include <string>

#include "mobb/crowd/record.h"

namespace mobb::crowd {

/// A record file's contents: the record, and its "summary" and "metrics" objects as JSON text (empty
/// when the file has none).
struct RecordFile {
    Record record;
    std::string summary_json, metrics_json;
};

/// Whether `file` names an HDF5 record (extension .h5 or .hdf5).
bool is_h5_record(const std::string& file);

/// Reads a record file of either kind, every field checked as load_record says. Throws
/// std::runtime_error, one line naming the file and the place: "FILE: PLACE: message" (a JSON place like
/// tracks[2].samples[7][3], an HDF5 one like /choices/agent block 3).
RecordFile read_record_file(const std::string& file);

/// Writes the record to `file` (its kind by extension), replacing it. Throws std::runtime_error
/// "FILE: cannot write ..." when the file cannot be written (a disk full, a missing folder).
void write_record_file(const std::string& file, const Record& record, const std::string& summary_json,
                       const std::string& metrics_json = "");

}  // namespace mobb::crowd
