#pragma once
// A thin RAII layer over HDF5's C API (libhdf5, https://docs.hdfgroup.org/hdf5/v1_10/): a file
// created whole, groups, n-dimensional datasets of doubles, floats and integers (chunked and
// compressed with HDF5's own shuffle + deflate filters, which every HDF5 reader decodes: h5py,
// ParaView, meshio), and scalar attributes. Row-major (C) order, as HDF5 stores: a dataset of dims
// {a, b} holds element (i, j) at data[i * b + j]. Every failure throws OutputError naming the file
// and the object. HDF5's own error printing is switched off: the exception says it once.
// The HDF5 headers stay in hdf5_file.cpp; identifiers are HDF5's hid_t (a 64-bit integer).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace stc::h5 {

/// One HDF5 object identifier, closed by its destructor with its kind's close function.
class Handle {
 public:
  enum class Kind { File, Group, Dataset, Dataspace, Property, Attribute, Datatype };
  Handle() = default;
  Handle(std::int64_t id, Kind kind) : id_(id), kind_(kind) {}
  ~Handle();
  Handle(Handle&& other) noexcept : id_(other.id_), kind_(other.kind_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  std::int64_t id() const { return id_; }
  /// The identifier, no longer closed by this handle.
  std::int64_t release() {
    const std::int64_t id = id_;
    id_ = -1;
    return id;
  }

 private:
  std::int64_t id_ = -1;
  Kind kind_ = Kind::File;
};

/// How a dataset is stored: contiguous, or in chunks of `chunk` (its rank's length) each passed
/// through shuffle + deflate at `level` (1: fastest, which is most of the gain on these fields).
struct Storage {
  std::vector<std::uint64_t> chunk;  ///< empty: contiguous, uncompressed
  int level = 1;
};

/// The chunk of a dataset of `dims` that keeps whole rows of the trailing dimensions and as many of
/// the first as fit in about `bytes` (at least one): "chunked by instant" for arrays whose first
/// dimension is time.
Storage chunkedByRows(const std::vector<std::uint64_t>& dims, std::size_t element_bytes,
                      std::size_t bytes = std::size_t{1} << 20);

/// The element types the file holds (HDF5's native types of this machine).
enum class Element { Float64, Float32, Int64, Int32, Int8 };
template <class T> constexpr Element elementOf();
template <> constexpr Element elementOf<double>() { return Element::Float64; }
template <> constexpr Element elementOf<float>() { return Element::Float32; }
template <> constexpr Element elementOf<std::int64_t>() { return Element::Int64; }
template <> constexpr Element elementOf<std::int32_t>() { return Element::Int32; }
template <> constexpr Element elementOf<std::int8_t>() { return Element::Int8; }

/// One chunk: its offset in the dataset and its bytes after shuffle + deflate (none: every element
/// 0, left unwritten, read back as the fill value 0).
struct Chunk {
  std::vector<std::uint64_t> offset;
  std::vector<unsigned char> bytes;
};

/// A dataset's chunks already passed through shuffle + deflate, ready for Group::write: what a
/// worker thread prepares (encode() calls no HDF5 function) while one thread writes the file.
struct Encoded {
  Element element = Element::Float64;
  std::vector<std::uint64_t> dims;
  Storage storage;
  std::vector<Chunk> chunks;
};

/// Encodes `data` (row-major, of `dims`) in chunks of chunkedByRows(dims, sizeof(T), bytes), on
/// the calling thread.
template <class T>
Encoded encode(const T* data, const std::vector<std::uint64_t>& dims, std::size_t bytes = std::size_t{1} << 20);

/// The chunk of chunkedByRows with the second dimension cut in blocks of `block`: histories of many
/// items (instant × contact node × component) whose far items stay 0, their chunks then unwritten.
Storage chunkedByBlocks(const std::vector<std::uint64_t>& dims, std::size_t element_bytes, std::uint64_t block,
                        std::size_t bytes = std::size_t{1} << 20);

class Group {
 public:
  Group(Handle handle, std::string where) : handle_(std::move(handle)), where_(std::move(where)) {}

  /// The subgroup `name`, created.
  Group group(const std::string& name) const;
  /// A dataset `name` of `dims` from `data` (product of dims elements, row-major).
  void write(const std::string& name, const double* data, const std::vector<std::uint64_t>& dims,
             const Storage& storage = {}) const;
  void write(const std::string& name, const float* data, const std::vector<std::uint64_t>& dims,
             const Storage& storage = {}) const;
  void write(const std::string& name, const std::int64_t* data, const std::vector<std::uint64_t>& dims,
             const Storage& storage = {}) const;
  void write(const std::string& name, const std::int32_t* data, const std::vector<std::uint64_t>& dims,
             const Storage& storage = {}) const;
  void write(const std::string& name, const std::int8_t* data, const std::vector<std::uint64_t>& dims,
             const Storage& storage = {}) const;
  /// A dataset `name` from chunks encoded beforehand.
  void write(const std::string& name, const Encoded& encoded) const;
  /// A one-dimensional dataset.
  template <class T>
  void write(const std::string& name, const std::vector<T>& values, const Storage& storage = {}) const {
    write(name, values.data(), {static_cast<std::uint64_t>(values.size())}, storage);
  }

  /// Scalar attributes of the group.
  void attribute(const std::string& name, double value) const;
  void attribute(const std::string& name, std::int64_t value) const;
  void attribute(const std::string& name, const std::string& value) const;
  void attribute(const std::string& name, const char* value) const { attribute(name, std::string(value)); }
  void attribute(const std::string& name, int value) const { attribute(name, static_cast<std::int64_t>(value)); }

  /// "file.h5:/path" of this group, for messages.
  const std::string& where() const { return where_; }

 private:
  Handle handle_;
  std::string where_;
  std::string pathOf(const std::string& name) const;  ///< "file.h5:/group/name", for messages
  Handle createDataset(const std::string& name, std::int64_t type, const std::vector<std::uint64_t>& dims,
                       const Storage& storage) const;
  void writeTyped(const std::string& name, std::int64_t type, const void* data, const std::vector<std::uint64_t>& dims,
                  const Storage& storage) const;
};

/// An HDF5 file created at `path` (replacing one there), its root group open.
class File {
 public:
  explicit File(const std::filesystem::path& path);
  /// The root group "/".
  const Group& root() const { return root_; }
  /// Flushes and closes the file; throws OutputError if HDF5 reports a failure.
  void close();

 private:
  std::filesystem::path path_;
  Handle file_;
  Group root_;
};

}  // namespace stc::h5
