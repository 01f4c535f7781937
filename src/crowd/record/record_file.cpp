// Record files by extension: JSON or HDF5 (include/mobb/crowd/record/record_file.h).
#include "mobb/crowd/record/record_file.h"

#include <algorithm>
#include <fstream>
#include <iostream>
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
    const std::string text = record_to_text(record, summary_json, metrics_json);
    std::ofstream f(file, std::ios::binary);
    f << text;
    f.flush();
    if (!f) throw std::runtime_error(file + ": cannot write");
}

}  // namespace mobb::crowd
