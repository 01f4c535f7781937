// What the two HDF5 record readers share - record_h5_read.cpp reads a file whole, record_h5_window.cpp in
// parts (record_reader.h): the file's header and the mark an incomplete file was written up to. Private
// to src/crowd.
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace mobb::crowd::h5read {

/// What a file holds: all of it once finished; up to its last mark ("written") when its writing stopped.
struct Held {
    bool complete = true;
    std::int64_t frames = 0, planned = 0;     ///< frames held; of the run
    std::map<std::string, std::size_t> rows;  ///< per table (group): the rows held

    /// The rows of dataset `path` to read.
    hsize_t limit(const std::string& path) const {
        const auto it = rows.find(path.substr(0, path.rfind('/')));
        return it == rows.end() ? ~hsize_t(0) : hsize_t(it->second);
    }
};

/// The file's attributes in the JSON layout (format .. metrics; "frames" those held), and its mark.
/// Throws h5::Error.
nlohmann::ordered_json header(hid_t file, Held& held);
/// "obstacles" of the JSON layout. Throws h5::Error.
nlohmann::ordered_json obstacles(hid_t file);
/// One line for an incomplete file (RecordFile::note), nothing for a finished one.
std::string note(const std::string& file, const Held& held);

/// A choice point's outcome by its number in /choices/outcome.
inline constexpr const char* kOutcomes[] = {"candidate", "escape", "arrived", "fallback", "right of way"};

}  // namespace mobb::crowd::h5read
