// Record files by extension: JSON or HDF5 (include/mobb/crowd/record_file.h).
#include "mobb/crowd/record_file.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "record_json.h"

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

SampleWindow read_sample_window(const std::string& file, std::int64_t first, std::int64_t last) {
    if (is_h5_record(file)) return read_h5_window(file, first, last);
    RecordFile r = read_json_record(file);
    SampleWindow w;
    w.dt = r.record.dt;
    w.frames = r.record.frames;
    w.agents = r.record.tracks.size();
    w.first = std::clamp<std::int64_t>(first, 0, w.frames);
    w.last = std::clamp<std::int64_t>(last, w.first, w.frames);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::int64_t f = w.first; f < w.last; ++f)
        for (const AgentTrack& t : r.record.tracks)
            w.samples.push_back(f < std::int64_t(t.samples.size()) ? t.samples[std::size_t(f)]
                                                                   : std::array<double, 4>{nan, nan, nan, nan});
    w.summary_json = std::move(r.summary_json);
    w.metrics_json = std::move(r.metrics_json);
    return w;
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
