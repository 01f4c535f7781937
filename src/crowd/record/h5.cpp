#include "record/h5.h"

#include <algorithm>
#include <cstring>

#include "mobb/core/assert.h"

namespace mobb::crowd::h5 {

Id& Id::operator=(Id&& o) noexcept {
    std::swap(id_, o.id_);
    std::swap(close_, o.close_);
    return *this;
}

Id::~Id() {
    if (id_ >= 0 && close_) close_(id_);
}

void quiet() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

template <>
hid_t native<std::int8_t>() {
    return H5T_NATIVE_INT8;
}
template <>
hid_t native<std::int32_t>() {
    return H5T_NATIVE_INT32;
}
template <>
hid_t native<std::int64_t>() {
    return H5T_NATIVE_INT64;
}
template <>
hid_t native<std::uint64_t>() {
    return H5T_NATIVE_UINT64;
}
template <>
hid_t native<double>() {
    return H5T_NATIVE_DOUBLE;
}

namespace {

// UTF-8 text of `size` bytes, padded with nulls.
Id text_type(std::size_t size) {
    Id t(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(t.get(), size);
    H5Tset_strpad(t.get(), H5T_STR_NULLPAD);
    H5Tset_cset(t.get(), H5T_CSET_UTF8);
    return t;
}

void check(herr_t status, const std::string& place, const char* what) {
    if (status < 0) throw Error(place + ": cannot " + what);
}

Id open_attribute(hid_t object, const char* name) {
    if (H5Aexists(object, name) <= 0) return {};
    return Id(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
}

// Removes attribute `name` if the object has one, so that it can be written anew.
void replace(hid_t object, const char* name) {
    if (H5Aexists(object, name) > 0 && H5Adelete(object, name) < 0)
        throw Error(std::string("attribute ") + name + ": cannot write");
}

// A dataset chunked as the writer chunks it: `block` rows and the whole of every inner dimension.
void check_chunks(hid_t set, const std::string& path, const std::vector<hsize_t>& dims, hsize_t block) {
    const Id dcpl(H5Dget_create_plist(set), H5Pclose);
    std::vector<hsize_t> chunk(dims.size(), 0);
    const int rank = int(dims.size());
    bool same = H5Pget_layout(dcpl.get()) == H5D_CHUNKED && H5Pget_chunk(dcpl.get(), rank, chunk.data()) == rank &&
                chunk[0] == block;
    for (std::size_t k = 1; k < dims.size(); ++k) same = same && chunk[k] == dims[k];
    if (!same) throw Error(path + ": not chunked as a record's (" + std::to_string(block) + " rows a block)");
}

}  // namespace

// Text is stored fixed-length, inside the attribute: a variable-length one lives in the file's global heap,
// and libhdf5 reads a damaged heap reference out of bounds (the record fuzzer's find), so the reader takes
// fixed-length text alone.
void write_text(hid_t object, const char* name, const std::string& text) {
    replace(object, name);
    const Id type = text_type(std::max<std::size_t>(1, text.size()));
    const Id space(H5Screate(H5S_SCALAR), H5Sclose);
    const Id a(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    std::string padded = text;
    padded.resize(std::max<std::size_t>(1, text.size()), '\0');
    check(a.valid() ? H5Awrite(a.get(), type.get(), padded.data()) : -1, std::string("attribute ") + name, "write");
}

template <class T>
void write_numbers(hid_t object, const char* name, const std::vector<T>& values) {
    replace(object, name);
    const hsize_t n = values.size();
    const Id space(values.size() == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose);
    const Id a(H5Acreate2(object, name, native<T>(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    check(a.valid() ? H5Awrite(a.get(), native<T>(), values.data()) : -1, std::string("attribute ") + name, "write");
}

std::optional<std::string> read_text(hid_t object, const char* name) {
    const Id a = open_attribute(object, name);
    if (!a.valid()) return std::nullopt;
    const Id type(H5Aget_type(a.get()), H5Tclose);
    const Id space(H5Aget_space(a.get()), H5Sclose);
    const std::string place = std::string("attribute ") + name;
    const std::size_t size = H5Tget_size(type.get());
    if (H5Tget_class(type.get()) != H5T_STRING || H5Sget_simple_extent_npoints(space.get()) != 1)
        throw Error(place + ": expected one text");
    if (H5Tis_variable_str(type.get()) != 0 || size < 1 || size > (std::size_t(1) << 26))
        throw Error(place + ": expected a fixed-length text of at most 64 MB");
    const Id mem = text_type(size);
    std::string out(size, '\0');
    check(H5Aread(a.get(), mem.get(), out.data()), place, "read");
    out.resize(std::strlen(out.c_str()));
    return out;
}

template <class T>
std::optional<std::vector<T>> read_numbers(hid_t object, const char* name) {
    const Id a = open_attribute(object, name);
    if (!a.valid()) return std::nullopt;
    const Id type(H5Aget_type(a.get()), H5Tclose);
    const Id space(H5Aget_space(a.get()), H5Sclose);
    const std::string place = std::string("attribute ") + name;
    const H5T_class_t c = H5Tget_class(type.get());
    const hssize_t n = H5Sget_simple_extent_npoints(space.get());
    if ((c != H5T_INTEGER && c != H5T_FLOAT) || n < 1 || n > 1024) throw Error(place + ": expected numbers");
    std::vector<T> out(static_cast<std::size_t>(n));
    check(H5Aread(a.get(), native<T>(), out.data()), place, "read");
    return out;
}

hsize_t row_size(const Layout& l) {
    hsize_t n = 1;
    for (hsize_t d : l.inner) n *= d;
    return n;
}

Appender::Appender(hid_t file, const std::string& path, hid_t type, const Layout& layout)
    : file_(file), type_(type), path_(path), layout_(layout) {
    layout_.block = std::max<hsize_t>(1, layout_.block);
    std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk{layout_.block};
    for (hsize_t d : layout_.inner) dims.push_back(d), max.push_back(d), chunk.push_back(std::max<hsize_t>(1, d));
    const int rank = int(dims.size());
    const Id space(H5Screate_simple(rank, dims.data(), max.data()), H5Sclose);
    const Id dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    H5Pset_chunk(dcpl.get(), rank, chunk.data());
    H5Pset_fletcher32(dcpl.get());  // a block damaged on disk is refused, not read as numbers
    if (layout_.compress) H5Pset_shuffle(dcpl.get()), H5Pset_deflate(dcpl.get(), 1);
    const Id lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    H5Pset_create_intermediate_group(lcpl.get(), 1);
    set_ = Id(H5Dcreate2(file, path.c_str(), type, space.get(), lcpl.get(), dcpl.get(), H5P_DEFAULT), H5Dclose);
    if (!set_.valid()) throw Error(path + ": cannot create");
}

void Appender::append(const void* data, hsize_t rows, bool flush) {
    if (rows == 0) return;
    std::vector<hsize_t> dims{rows_ + rows}, start{rows_}, counts{rows};
    for (hsize_t d : layout_.inner) dims.push_back(d), start.push_back(0), counts.push_back(d);
    const int rank = int(dims.size());
    const std::string block = path_ + " block " + std::to_string(rows_ / layout_.block);
    if (H5Dset_extent(set_.get(), dims.data()) < 0) throw Error(block + ": cannot write");
    const Id file_space(H5Dget_space(set_.get()), H5Sclose);
    H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, counts.data(), nullptr);
    const Id mem(H5Screate_simple(rank, counts.data(), nullptr), H5Sclose);
    if (H5Dwrite(set_.get(), type_, mem.get(), file_space.get(), H5P_DEFAULT, data) < 0 ||
        (flush && H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0))
        throw Error(block + ": cannot write");
    rows_ += rows;
}

template <class T>
void write_rows(hid_t file, const std::string& path, hsize_t rows, const Layout& layout,
                const std::function<void(hsize_t, hsize_t, T*)>& fill) {
    Appender out(file, path, native<T>(), layout);
    const hsize_t block = std::max<hsize_t>(1, layout.block);
    std::vector<T> buffer(std::size_t(block * row_size(layout)));
    for (hsize_t first = 0; first < rows; first += block) {
        const hsize_t count = std::min(block, rows - first);
        fill(first, count, buffer.data());
        out.append(buffer.data(), count);
    }
}

template <class T>
void write_rows(hid_t file, const std::string& path, const std::vector<T>& data, const Layout& layout) {
    const hsize_t size = row_size(layout);
    write_rows<T>(file, path, data.size() / size, layout, [&](hsize_t first, hsize_t count, T* out) {
        std::copy_n(data.data() + first * size, count * size, out);
    });
}

namespace {

// Dataset `path` of rows of numbers shaped [rows, inner...] and chunked as the writer chunks it (`block`
// rows): the dataset, its dims in `dims`. Throws Error when it is something else.
Id open_rows(hid_t file, const std::string& path, const std::vector<hsize_t>& inner, hsize_t block,
             std::vector<hsize_t>& dims) {
    Id set(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid()) throw Error(path + ": cannot open (not a dataset, or corrupt)");
    const Id space(H5Dget_space(set.get()), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    dims.assign(std::size_t(std::max(rank, 0)), 0);
    if (rank != int(inner.size()) + 1 || H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0 ||
        !std::equal(inner.begin(), inner.end(), dims.begin() + 1))
        throw Error(path + ": unexpected shape");
    const Id type(H5Dget_type(set.get()), H5Tclose);
    const H5T_class_t c = H5Tget_class(type.get());
    if (c != H5T_INTEGER && c != H5T_FLOAT) throw Error(path + ": expected numbers");
    check_chunks(set.get(), path, dims, block);
    hsize_t size = 1;
    for (hsize_t d : inner) size *= d;
    if (dims[0] > (hsize_t(1) << 40) / std::max<hsize_t>(1, size)) throw Error(path + ": too large");
    return set;
}

// Rows first .. first + count - 1 of the dataset (dims `dims`) into `out`, in the memory type of T (HDF5
// converts whatever integer or float type the file holds). False when HDF5 cannot read them.
template <class T>
bool read_slab(hid_t set, const std::vector<hsize_t>& dims, hsize_t first, hsize_t count, T* out) {
    std::vector<hsize_t> start(dims.size(), 0), counts = dims;
    start[0] = first, counts[0] = count;
    const Id file_space(H5Dget_space(set), H5Sclose);
    if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, counts.data(), nullptr) < 0)
        return false;
    const Id mem(H5Screate_simple(int(dims.size()), counts.data(), nullptr), H5Sclose);
    return H5Dread(set, native<T>(), mem.get(), file_space.get(), H5P_DEFAULT, out) >= 0;
}

}  // namespace

template <class T>
std::optional<std::vector<T>> read_rows(hid_t file, const std::string& path, const std::vector<hsize_t>& inner,
                                        hsize_t limit, hsize_t block) {
    if (H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0) return std::nullopt;
    std::vector<hsize_t> dims;
    const Id set = open_rows(file, path, inner, block, dims);
    const hsize_t rows = std::min(dims[0], limit), size = row_size(Layout{inner});
    std::vector<T> out(std::size_t(rows * size));
    for (hsize_t first = 0, k = 0; first < rows; first += block, ++k)
        if (!read_slab(set.get(), dims, first, std::min(block, rows - first), out.data() + first * size))
            throw Error(path + " block " + std::to_string(k) + ": cannot read (truncated or corrupt)");
    return out;
}

template <class T>
Column<T>::Column(hid_t file, const std::string& path, const std::vector<hsize_t>& inner, hsize_t block, hsize_t limit)
    : path_(path), block_(std::max<hsize_t>(1, block)), size_(row_size(Layout{inner})) {
    if (H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0) throw Error(path + ": missing");
    set_ = open_rows(file, path, inner, block_, dims_);
    rows_ = std::min(dims_[0], limit);
}

template <class T>
void Column<T>::read_into(hsize_t first, hsize_t count, T* out) {
    if (first > rows_ || count > rows_ - first)
        throw Error(path_ + ": rows " + std::to_string(first) + " to " + std::to_string(first + count) + ", it has " +
                    std::to_string(rows_));
    for (hsize_t row = first; row < first + count;) {  // a block at a time, so that an error names it
        const hsize_t k = row / block_, n = std::min((k + 1) * block_, first + count) - row;
        if (!read_slab(set_.get(), dims_, row, n, out + (row - first) * size_))
            throw Error(path_ + " block " + std::to_string(k) + ": cannot read (truncated or corrupt)");
        row += n;
    }
}

template <class T>
std::vector<T> Column<T>::read(hsize_t first, hsize_t count) {
    if (count > 0 && first < rows_ && first / block_ == (first + count - 1) / block_ && block_ * size_ <= kKeptValues) {
        const std::vector<T>& b = kept(first / block_);  // a few rows of a table: from the block kept
        const hsize_t at = first % block_;
        if (at + count <= b.size() / size_)
            return std::vector<T>(b.begin() + std::ptrdiff_t(at * size_),
                                  b.begin() + std::ptrdiff_t((at + count) * size_));
    }
    std::vector<T> out(std::size_t(count * size_));
    read_into(first, count, out.data());
    return out;
}

template <class T>
const std::vector<T>& Column<T>::kept(hsize_t k) {
    auto it = std::find_if(kept_.begin(), kept_.end(), [&](const auto& b) { return b.first == k; });
    if (it == kept_.end()) {
        std::vector<T> values(std::size_t(std::min(block_, rows_ - k * block_) * size_));
        read_into(k * block_, values.size() / size_, values.data());
        if (kept_.size() == kKeptBlocks) kept_.pop_back();
        kept_.emplace_back(k, std::move(values));
        it = std::prev(kept_.end());
    }
    std::rotate(kept_.begin(), it, std::next(it));  // the last used first
    return kept_.front().second;
}

template <class T>
T Column<T>::at(hsize_t row) {
    MOBB_ASSERT(size_ == 1);
    if (row >= rows_) throw Error(path_ + ": row " + std::to_string(row) + ", it has " + std::to_string(rows_));
    return kept(row / block_)[std::size_t(row % block_)];
}

template <class T>
hsize_t Column<T>::lower_bound(T value, hsize_t lo, hsize_t hi) {
    hi = std::min(hi, rows_);
    while (lo < hi) {
        const hsize_t mid = lo + (hi - lo) / 2;
        if (at(mid) < value)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

template class Column<std::int64_t>;
template class Column<double>;
template void write_numbers(hid_t, const char*, const std::vector<std::int64_t>&);
template void write_numbers(hid_t, const char*, const std::vector<std::uint64_t>&);
template void write_numbers(hid_t, const char*, const std::vector<double>&);
template std::optional<std::vector<std::int64_t>> read_numbers(hid_t, const char*);
template std::optional<std::vector<std::uint64_t>> read_numbers(hid_t, const char*);
template std::optional<std::vector<double>> read_numbers(hid_t, const char*);
template void write_rows(hid_t, const std::string&, hsize_t, const Layout&,
                         const std::function<void(hsize_t, hsize_t, std::int64_t*)>&);
template void write_rows(hid_t, const std::string&, hsize_t, const Layout&,
                         const std::function<void(hsize_t, hsize_t, double*)>&);
template void write_rows(hid_t, const std::string&, const std::vector<std::int64_t>&, const Layout&);
template void write_rows(hid_t, const std::string&, const std::vector<double>&, const Layout&);
template std::optional<std::vector<std::int64_t>> read_rows(hid_t, const std::string&, const std::vector<hsize_t>&,
                                                            hsize_t, hsize_t);
template std::optional<std::vector<double>> read_rows(hid_t, const std::string&, const std::vector<hsize_t>&, hsize_t,
                                                      hsize_t);

}  // namespace mobb::crowd::h5
