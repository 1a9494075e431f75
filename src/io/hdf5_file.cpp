#include "stcontact/io/hdf5_file.hpp"

#include <hdf5.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "stcontact/core/threads.hpp"
#include "stcontact/io/output_error.hpp"

namespace stc::h5 {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "HDF5 1.10 or later: hid_t is a 64-bit integer");

/// HDF5 prints its error stack on every failed call unless told not to; the exceptions below say
/// what failed once.
void silenceHdf5() {
  static const bool silenced = [] { return H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0; }();
  (void)silenced;
}

[[noreturn]] void fail(const std::string& what, const std::string& where) {
  throw OutputError("cannot write '" + where + "': HDF5 failed to " + what);
}

hid_t created(hid_t id, const std::string& what, const std::string& where) {
  if (id < 0) fail(what, where);
  return id;
}

void checked(herr_t status, const std::string& what, const std::string& where) {
  if (status < 0) fail(what, where);
}

std::vector<hsize_t> hsizes(const std::vector<std::uint64_t>& dims) { return {dims.begin(), dims.end()}; }

bool hasNoElement(const std::vector<std::uint64_t>& dims) {
  return std::any_of(dims.begin(), dims.end(), [](std::uint64_t d) { return d == 0; });
}

Handle dataspace(const std::vector<std::uint64_t>& dims, const std::string& where) {
  const std::vector<hsize_t> sizes = hsizes(dims);
  return {created(H5Screate_simple(static_cast<int>(sizes.size()), sizes.data(), nullptr), "create a dataspace", where),
          Handle::Kind::Dataspace};
}

// The dataset creation properties: contiguous, or chunked with shuffle + deflate.
Handle creationProperties(const Storage& storage, const std::vector<std::uint64_t>& dims, const std::string& where) {
  Handle props{created(H5Pcreate(H5P_DATASET_CREATE), "create dataset properties", where), Handle::Kind::Property};
  // No modification times in the object headers: the same run writes the same bytes.
  checked(H5Pset_obj_track_times(props.id(), 0), "drop the time stamps", where);
  if (storage.chunk.empty() || hasNoElement(dims)) return props;
  if (storage.chunk.size() != dims.size()) fail("chunk a dataset (the chunk's rank is not the dataset's)", where);
  const std::vector<hsize_t> chunk = hsizes(storage.chunk);
  checked(H5Pset_chunk(props.id(), static_cast<int>(chunk.size()), chunk.data()), "set the chunks", where);
  checked(H5Pset_shuffle(props.id()), "set the shuffle filter", where);
  checked(H5Pset_deflate(props.id(), static_cast<unsigned>(storage.level)), "set the deflate filter", where);
  return props;
}

void writeAttribute(hid_t owner, const std::string& name, hid_t type, const void* value, const std::string& where) {
  Handle space{created(H5Screate(H5S_SCALAR), "create a scalar dataspace", where), Handle::Kind::Dataspace};
  Handle attribute{created(H5Acreate2(owner, name.c_str(), type, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                           "create attribute " + name, where),
                   Handle::Kind::Attribute};
  checked(H5Awrite(attribute.id(), type, value), "write an attribute", where);
}

// Shuffle (the bytes of each element's significance together: byte b of element i at b n + i) then
// deflate, as HDF5's H5Z_FILTER_SHUFFLE and H5Z_FILTER_DEFLATE do in that order, so that any reader
// decodes the chunk through the dataset's declared filters.
std::vector<unsigned char> encodedChunk(const unsigned char* data, std::size_t elements, std::size_t element_bytes,
                                        int level) {
  const std::size_t bytes = elements * element_bytes;
  std::vector<unsigned char> shuffled(bytes);
  for (std::size_t i = 0; i < elements; ++i)
    for (std::size_t b = 0; b < element_bytes; ++b) shuffled[b * elements + i] = data[i * element_bytes + b];
  uLongf size = compressBound(static_cast<uLong>(bytes));
  std::vector<unsigned char> out(size);
  if (compress2(out.data(), &size, shuffled.data(), static_cast<uLong>(bytes), level) != Z_OK) out.clear();
  else out.resize(size);
  return out;
}

hid_t nativeType(Element element) {
  switch (element) {
    case Element::Float64: return H5T_NATIVE_DOUBLE;
    case Element::Float32: return H5T_NATIVE_FLOAT;
    case Element::Int64: return H5T_NATIVE_INT64;
    case Element::Int32: return H5T_NATIVE_INT32;
    case Element::Int8: return H5T_NATIVE_INT8;
  }
  return H5T_NATIVE_DOUBLE;
}

// Whether `storage`'s chunks are blocks of the first two dimensions, every further one whole: the
// chunks this file encodes itself (chunkedByRows, chunkedByBlocks).
bool chunksAreBlocks(const std::vector<std::uint64_t>& dims, const Storage& storage) {
  if (storage.chunk.size() != dims.size() || dims.empty()) return false;
  for (std::size_t a = 2; a < dims.size(); ++a)
    if (storage.chunk[a] != dims[a]) return false;
  return true;
}

// The chunk grid of a block layout: chunks along the first and the second dimension.
std::pair<std::size_t, std::size_t> chunkGrid(const std::vector<std::uint64_t>& dims, const Storage& storage) {
  const auto along = [&](std::size_t a) {
    return a < dims.size() ? static_cast<std::size_t>((dims[a] + storage.chunk[a] - 1) / storage.chunk[a]) : std::size_t{1};
  };
  return {along(0), along(1)};
}

// Whether every byte is 0, read a word at a time (the test runs over every array written).
bool allZero(const std::vector<unsigned char>& bytes) {
  std::uint64_t any = 0;
  const std::size_t words = bytes.size() / 8;
  for (std::size_t w = 0; w < words; ++w) {
    std::uint64_t word;
    std::memcpy(&word, bytes.data() + 8 * w, 8);
    any |= word;
  }
  for (std::size_t b = 8 * words; b < bytes.size(); ++b) any |= bytes[b];
  return any == 0;
}

// Chunk (c0, c1) of a block layout, gathered (the edge chunks padded with zeros to their full size,
// as HDF5 stores them) and encoded; none when every element is zero: a chunk never written reads
// as the fill value, 0.
Chunk encodeBlock(const unsigned char* data, std::size_t element_bytes, const std::vector<std::uint64_t>& dims,
                  const Storage& storage, std::size_t c0, std::size_t c1) {
  std::size_t tail = element_bytes;  // bytes of one entry of the second dimension
  for (std::size_t a = 2; a < dims.size(); ++a) tail *= dims[a];
  const std::size_t width = dims.size() > 1 ? dims[1] : 1, block = dims.size() > 1 ? storage.chunk[1] : 1;
  const std::size_t first0 = c0 * storage.chunk[0], first1 = c1 * block;
  const std::size_t rows = std::min<std::size_t>(storage.chunk[0], dims[0] - first0);
  const std::size_t cols = std::min<std::size_t>(block, width - first1);
  std::vector<unsigned char> gathered(storage.chunk[0] * block * tail, 0);
  for (std::size_t r = 0; r < rows; ++r)
    std::memcpy(gathered.data() + r * block * tail, data + ((first0 + r) * width + first1) * tail, cols * tail);
  Chunk chunk{{first0, first1}, {}};
  chunk.offset.resize(dims.size(), 0);
  if (allZero(gathered)) return chunk;
  chunk.bytes = encodedChunk(gathered.data(), gathered.size() / element_bytes, element_bytes, storage.level);
  if (chunk.bytes.empty()) throw std::runtime_error("deflate failed");
  return chunk;
}

// Every chunk of a block layout encoded, on every thread when `parallel`.
std::vector<Chunk> encodeBlocks(const void* data, std::size_t element_bytes, const std::vector<std::uint64_t>& dims,
                                const Storage& storage, bool parallel) {
  const std::pair<std::size_t, std::size_t> grid = chunkGrid(dims, storage);
  const std::size_t n0 = grid.first, n1 = grid.second;  // (not a structured binding: clang 14 cannot capture one)
  std::vector<Chunk> chunks(n0 * n1);
  const auto* bytes = static_cast<const unsigned char*>(data);
  const auto encodeOne = [&](int c, int) {
    const auto i = static_cast<std::size_t>(c);
    chunks[i] = encodeBlock(bytes, element_bytes, dims, storage, i / n1, i % n1);
  };
  if (parallel) parallelFor(static_cast<int>(chunks.size()), threadCount(), encodeOne);
  else
    for (int c = 0; c < static_cast<int>(chunks.size()); ++c) encodeOne(c, 0);
  return chunks;
}

// The encoded chunks into `dataset` as they are (H5Dwrite_chunk: no filter run again); all-zero
// chunks are left unwritten.
void writeChunks(hid_t dataset, const std::vector<Chunk>& chunks, const std::string& where) {
  for (const Chunk& chunk : chunks) {
    if (chunk.bytes.empty()) continue;
    const std::vector<hsize_t> offset(chunk.offset.begin(), chunk.offset.end());
    checked(H5Dwrite_chunk(dataset, H5P_DEFAULT, 0, offset.data(), chunk.bytes.size(), chunk.bytes.data()),
            "write a chunk", where);
  }
}

}  // namespace

Handle::~Handle() {
  if (id_ < 0) return;
  switch (kind_) {
    case Kind::File: H5Fclose(id_); break;
    case Kind::Group: H5Gclose(id_); break;
    case Kind::Dataset: H5Dclose(id_); break;
    case Kind::Dataspace: H5Sclose(id_); break;
    case Kind::Property: H5Pclose(id_); break;
    case Kind::Attribute: H5Aclose(id_); break;
    case Kind::Datatype: H5Tclose(id_); break;
  }
}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    Handle old(std::move(*this));
    id_ = other.id_;
    kind_ = other.kind_;
    other.id_ = -1;
  }
  return *this;
}

Storage chunkedByBlocks(const std::vector<std::uint64_t>& dims, std::size_t element_bytes, std::uint64_t block,
                        std::size_t bytes) {
  if (dims.size() < 2) return chunkedByRows(dims, element_bytes, bytes);
  std::vector<std::uint64_t> narrowed = dims;
  narrowed[1] = std::clamp<std::uint64_t>(block, 1, std::max<std::uint64_t>(dims[1], 1));
  return chunkedByRows(narrowed, element_bytes, bytes);
}

Storage chunkedByRows(const std::vector<std::uint64_t>& dims, std::size_t element_bytes, std::size_t bytes) {
  if (dims.empty()) return {};
  std::uint64_t row = element_bytes;
  for (std::size_t a = 1; a < dims.size(); ++a) row *= std::max<std::uint64_t>(dims[a], 1);
  Storage storage;
  storage.chunk = dims;
  storage.chunk[0] = std::clamp<std::uint64_t>(bytes / std::max<std::uint64_t>(row, 1), 1, std::max<std::uint64_t>(dims[0], 1));
  for (std::uint64_t& c : storage.chunk) c = std::max<std::uint64_t>(c, 1);
  return storage;
}

Group Group::group(const std::string& name) const {
  const std::string where = pathOf(name);
  const Handle props{created(H5Pcreate(H5P_GROUP_CREATE), "create group properties", where), Handle::Kind::Property};
  checked(H5Pset_obj_track_times(props.id(), 0), "drop the time stamps", where);
  return {Handle{created(H5Gcreate2(handle_.id(), name.c_str(), H5P_DEFAULT, props.id(), H5P_DEFAULT),
                         "create group " + name, where),
                 Handle::Kind::Group},
          where};
}

std::string Group::pathOf(const std::string& name) const { return where_ + (where_.back() == '/' ? "" : "/") + name; }

Handle Group::createDataset(const std::string& name, std::int64_t type, const std::vector<std::uint64_t>& dims,
                            const Storage& storage) const {
  const std::string where = pathOf(name);
  const Handle space = dataspace(dims, where);
  const Handle props = creationProperties(storage, dims, where);
  return {created(H5Dcreate2(handle_.id(), name.c_str(), type, space.id(), H5P_DEFAULT, props.id(), H5P_DEFAULT),
                  "create the dataset", where),
          Handle::Kind::Dataset};
}

void Group::writeTyped(const std::string& name, std::int64_t type, const void* data,
                       const std::vector<std::uint64_t>& dims, const Storage& storage) const {
  const Handle dataset = createDataset(name, type, dims, storage);
  if (hasNoElement(dims)) return;
  if (chunksAreBlocks(dims, storage)) {  // encoded on every thread, written in order
    writeChunks(dataset.id(), encodeBlocks(data, H5Tget_size(static_cast<hid_t>(type)), dims, storage, true), pathOf(name));
    return;
  }
  checked(H5Dwrite(dataset.id(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write the dataset", pathOf(name));
}

void Group::write(const std::string& name, const Encoded& encoded) const {
  const Handle dataset = createDataset(name, nativeType(encoded.element), encoded.dims, encoded.storage);
  writeChunks(dataset.id(), encoded.chunks, pathOf(name));
}

template <class T>
Encoded encode(const T* data, const std::vector<std::uint64_t>& dims, std::size_t bytes) {
  Encoded encoded{elementOf<T>(), dims, chunkedByRows(dims, sizeof(T), bytes), {}};
  if (!hasNoElement(dims)) encoded.chunks = encodeBlocks(data, sizeof(T), dims, encoded.storage, false);
  return encoded;
}

template Encoded encode(const double*, const std::vector<std::uint64_t>&, std::size_t);
template Encoded encode(const float*, const std::vector<std::uint64_t>&, std::size_t);
template Encoded encode(const std::int64_t*, const std::vector<std::uint64_t>&, std::size_t);
template Encoded encode(const std::int32_t*, const std::vector<std::uint64_t>&, std::size_t);
template Encoded encode(const std::int8_t*, const std::vector<std::uint64_t>&, std::size_t);

void Group::write(const std::string& name, const double* data, const std::vector<std::uint64_t>& dims,
                  const Storage& storage) const {
  writeTyped(name, H5T_NATIVE_DOUBLE, data, dims, storage);
}
void Group::write(const std::string& name, const float* data, const std::vector<std::uint64_t>& dims,
                  const Storage& storage) const {
  writeTyped(name, H5T_NATIVE_FLOAT, data, dims, storage);
}
void Group::write(const std::string& name, const std::int64_t* data, const std::vector<std::uint64_t>& dims,
                  const Storage& storage) const {
  writeTyped(name, H5T_NATIVE_INT64, data, dims, storage);
}
void Group::write(const std::string& name, const std::int32_t* data, const std::vector<std::uint64_t>& dims,
                  const Storage& storage) const {
  writeTyped(name, H5T_NATIVE_INT32, data, dims, storage);
}
void Group::write(const std::string& name, const std::int8_t* data, const std::vector<std::uint64_t>& dims,
                  const Storage& storage) const {
  writeTyped(name, H5T_NATIVE_INT8, data, dims, storage);
}

void Group::attribute(const std::string& name, double value) const {
  writeAttribute(handle_.id(), name, H5T_NATIVE_DOUBLE, &value, where_);
}

void Group::attribute(const std::string& name, std::int64_t value) const {
  writeAttribute(handle_.id(), name, H5T_NATIVE_INT64, &value, where_);
}

void Group::attribute(const std::string& name, const std::string& value) const {
  // A variable-length UTF-8 string: h5py reads it as str (a fixed-length one comes back as bytes).
  const Handle type{created(H5Tcopy(H5T_C_S1), "copy the string type", where_), Handle::Kind::Datatype};
  checked(H5Tset_size(type.id(), H5T_VARIABLE), "size a string type", where_);
  checked(H5Tset_cset(type.id(), H5T_CSET_UTF8), "set a string's character set", where_);
  const char* text = value.c_str();
  writeAttribute(handle_.id(), name, type.id(), &text, where_);
}

namespace {

// The file format of HDF5 1.10 and later (readers from 2016 on: h5py, ParaView, meshio): compact
// object headers, and no B-tree for a dataset of one chunk, which keeps a frame's small datasets
// small (201 frames of the seed scene: 5.4 MB instead of 8.1 MB). The root group without time stamps,
// as every group and dataset (a file creation list is a group creation list): the same solution
// gives the same bytes whenever it is written.
Handle createFile(const std::filesystem::path& path) {
  silenceHdf5();
  const std::string where = path.string();
  const Handle access{created(H5Pcreate(H5P_FILE_ACCESS), "create file access properties", where), Handle::Kind::Property};
  checked(H5Pset_libver_bounds(access.id(), H5F_LIBVER_V110, H5F_LIBVER_LATEST), "choose the file format", where);
  const Handle creation{created(H5Pcreate(H5P_FILE_CREATE), "create file creation properties", where), Handle::Kind::Property};
  checked(H5Pset_obj_track_times(creation.id(), 0), "drop the root group's time stamps", where);
  return {created(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, creation.id(), access.id()), "create the file", where),
          Handle::Kind::File};
}

Handle openRoot(const Handle& file, const std::string& where) {
  return {created(H5Gopen2(file.id(), "/", H5P_DEFAULT), "open the root group", where), Handle::Kind::Group};
}

}  // namespace

File::File(const std::filesystem::path& path)
    : path_(path), file_(createFile(path)), root_(openRoot(file_, path.string() + ":/"), path.string() + ":/") {}

void File::close() {
  root_ = Group(Handle{}, root_.where());  // every object closed before the file
  checked(H5Fclose(static_cast<hid_t>(file_.release())), "close the file", path_.string());
}

}  // namespace stc::h5
