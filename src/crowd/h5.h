// A thin layer over HDF5's C API for the record files (record_h5_write.cpp, record_h5_read.cpp): ids that
// close themselves, attributes, and datasets of rows of integers (8 to 64 bits) or float64 written and
// read in blocks of rows (the dataset's chunks), so an error names the block.
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mobb::crowd::h5 {

/// A problem with the file: "PLACE: message" (the caller puts the file name in front).
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// An HDF5 id, closed by its own close function when it goes.
class Id {
public:
    Id() = default;
    Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
    Id(Id&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
    Id& operator=(Id&& o) noexcept;
    Id(const Id&) = delete;
    Id& operator=(const Id&) = delete;
    ~Id();
    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }

private:
    hid_t id_ = -1;
    herr_t (*close_)(hid_t) = nullptr;
};

/// Keeps HDF5 from printing its error stack: the caller reports each problem in one line.
void quiet();

template <class T>
hid_t native();  // std::int8_t, std::int32_t, std::int64_t, std::uint64_t, double

// Attributes: text (variable-length UTF-8), numbers and arrays of numbers; writing one replaces it.
void write_text(hid_t object, const char* name, const std::string& text);
template <class T>
void write_numbers(hid_t object, const char* name, const std::vector<T>& values);  ///< one value: a scalar
std::optional<std::string> read_text(hid_t object, const char* name);
template <class T>
std::optional<std::vector<T>> read_numbers(hid_t object, const char* name);

/// A dataset of `rows` rows of `inner` values each (dims [rows, inner...]; [rows] when inner is empty),
/// chunked by `block` rows and extendible in rows; created with its intermediate groups. Integer columns
/// are shuffled and deflated (they shrink many times); doubles - the samples, the tables' real columns -
/// are not (they barely shrink, and the writing time counts).
struct Layout {
    std::vector<hsize_t> inner;
    hsize_t block = 4096;
    bool compress = true;
};
hsize_t row_size(const Layout& l);

/// A new dataset `path` of rows (Layout) that grows as rows are appended: each append writes its rows,
/// whole blocks at a time but for the last, and flushes the file unless told not to.
class Appender {
public:
    Appender(hid_t file, const std::string& path, hid_t type, const Layout& layout);
    /// Appends `rows` rows (rows * row_size values of the dataset's type at `data`).
    void append(const void* data, hsize_t rows, bool flush = true);
    hsize_t rows() const { return rows_; }
    const Layout& layout() const { return layout_; }

private:
    hid_t file_ = -1, type_ = -1;
    std::string path_;
    Layout layout_;
    Id set_;
    hsize_t rows_ = 0;
};

/// Writes `rows` rows as a new dataset `path`, block by block - `fill(first, count, out)` puts rows
/// first .. first + count - 1 in `out` - flushing the file after each block, so that what is on disk stays
/// readable up to the last complete block.
template <class T>
void write_rows(hid_t file, const std::string& path, hsize_t rows, const Layout& layout,
                const std::function<void(hsize_t first, hsize_t count, T* out)>& fill);
/// The same from `data` (rows * row_size values).
template <class T>
void write_rows(hid_t file, const std::string& path, const std::vector<T>& data, const Layout& layout);

/// Reads dataset `path` whole - or its first `limit` rows - block by block (an error names the block);
/// checks its shape against `inner` (the dims after the rows) and its chunks against the writer's, `block`
/// rows (libhdf5 1.10 copies a chunk as large as its layout says, whatever the chunk holds). Nothing when
/// the file has no such dataset.
template <class T>
std::optional<std::vector<T>> read_rows(hid_t file, const std::string& path, const std::vector<hsize_t>& inner,
                                        hsize_t limit = ~hsize_t(0), hsize_t block = 4096);

/// Rows first .. first + count - 1 of dataset `path` (shape checked as read_rows does), read alone.
template <class T>
std::vector<T> read_window(hid_t file, const std::string& path, const std::vector<hsize_t>& inner, hsize_t first,
                           hsize_t count, hsize_t block);

}  // namespace mobb::crowd::h5
