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

/// The HDF5 memory type of T: one of the five below.
template <class T>
hid_t native();
template <>
hid_t native<std::int8_t>();
template <>
hid_t native<std::int32_t>();
template <>
hid_t native<std::int64_t>();
template <>
hid_t native<std::uint64_t>();
template <>
hid_t native<double>();

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

/// One dataset of rows (a table's column, or the samples), kept open for reads of ranges and of single
/// rows, block by block (an error names the block: "PATH block K: cannot read (truncated or corrupt)");
/// the last kKeptBlocks blocks of a table that single rows or a few rows came from are kept for the next
/// (a binary search visits the same few again; one choice point's rows lie together). Its shape and chunks are checked as read_rows checks them when it opens; rows past
/// `limit` are not read.
template <class T>
class Column {
public:
    Column() = default;
    /// Throws Error "PATH: missing" when the file has no such dataset.
    Column(hid_t file, const std::string& path, const std::vector<hsize_t>& inner, hsize_t block = 4096,
           hsize_t limit = ~hsize_t(0));
    hsize_t rows() const { return rows_; }
    hsize_t block() const { return block_; }
    const std::string& path() const { return path_; }
    /// Rows first .. first + count - 1 (row_size values each); Error "PATH: rows ..., it has N" past the end.
    std::vector<T> read(hsize_t first, hsize_t count);
    /// Row `row` of a column of one value a row.
    T at(hsize_t row);
    /// The first row in [lo, hi) whose value is not less than `value`, the column sorted there (hi when
    /// none); on a column that is not sorted, some row in [lo, hi].
    hsize_t lower_bound(T value, hsize_t lo, hsize_t hi);

private:
    void read_into(hsize_t first, hsize_t count, T* out);
    const std::vector<T>& kept(hsize_t block);  // block `block`, read unless kept

    static constexpr std::size_t kKeptBlocks = 16;             // 512 KB of a column of 4,096-row blocks of 8 bytes
    static constexpr hsize_t kKeptValues = hsize_t(4096) * 4;  // tables' blocks are kept, not the samples'

    Id set_;
    std::string path_;
    std::vector<hsize_t> dims_;
    hsize_t rows_ = 0, block_ = 1, size_ = 1;
    std::vector<std::pair<hsize_t, std::vector<T>>> kept_;  // blocks by index, the last used first
};

}  // namespace mobb::crowd::h5
