#include "stcontact/io/hdf5_reader.hpp"

#include <hdf5.h>

#include <memory>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"

namespace stc::h5 {
namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw InputError("cannot read '" + where + "': " + what);
}

Handle opened(hid_t id, Handle::Kind kind, const std::string& where, const std::string& what) {
  if (id < 0) fail(where, what);
  return {id, kind};
}

Handle openFile(const std::filesystem::path& path) {
  if (MissingFileError::isMissing(path))
    throw MissingFileError("cannot read '" + path.string() + "': no such file", path.string());
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // the exception says what failed, once
  return opened(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), Handle::Kind::File, path.string(),
                "not an HDF5 file HDF5 can open");
}

bool isNumeric(hid_t type) {
  const H5T_class_t c = H5Tget_class(type);
  return c == H5T_INTEGER || c == H5T_FLOAT;
}

}  // namespace

Reader::Reader(const std::filesystem::path& path) : file_(path.string()), handle_(openFile(path)) {}

DoubleArray Reader::doubles(const std::string& path) const {
  const std::string where = this->where(path);
  // H5Lexists asks every group on the way to exist: each link checked from the root down.
  for (std::size_t end = path.find('/', 1);; end = path.find('/', end + 1)) {
    if (H5Lexists(handle_.id(), path.substr(0, end).c_str(), H5P_DEFAULT) <= 0) fail(where, "no such dataset");
    if (end == std::string::npos) break;
  }
  const Handle dataset =
      opened(H5Dopen2(handle_.id(), path.c_str(), H5P_DEFAULT), Handle::Kind::Dataset, where, "not a dataset");
  const Handle type = opened(H5Dget_type(dataset.id()), Handle::Kind::Datatype, where, "no type");
  if (!isNumeric(type.id())) fail(where, "not an array of numbers");
  const Handle space = opened(H5Dget_space(dataset.id()), Handle::Kind::Dataspace, where, "no dataspace");
  const int rank = H5Sget_simple_extent_ndims(space.id());
  if (rank < 0) fail(where, "no simple dataspace");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
  DoubleArray out{{dims.begin(), dims.end()}, {}};
  std::uint64_t count = 1;
  for (const hsize_t d : dims) count *= d;
  out.values.resize(count);
  if (count > 0 && H5Dread(dataset.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data()) < 0)
    fail(where, "HDF5 failed to read it");
  return out;
}

bool Reader::hasAttribute(const std::string& name) const { return H5Aexists(handle_.id(), name.c_str()) > 0; }

Handle Reader::attribute(const std::string& name) const {
  const std::string where = this->where("/ attribute " + name);
  if (!hasAttribute(name)) fail(where, "no such attribute");
  return opened(H5Aopen(handle_.id(), name.c_str(), H5P_DEFAULT), Handle::Kind::Attribute, where, "cannot open it");
}

double Reader::number(const std::string& name) const {
  const std::string where = this->where("/ attribute " + name);
  const Handle attribute = this->attribute(name);
  const Handle type = opened(H5Aget_type(attribute.id()), Handle::Kind::Datatype, where, "no type");
  if (!isNumeric(type.id())) fail(where, "not a number");
  double value = 0.0;
  if (H5Aread(attribute.id(), H5T_NATIVE_DOUBLE, &value) < 0) fail(where, "HDF5 failed to read it");
  return value;
}

std::string Reader::text(const std::string& name) const {
  const std::string where = this->where("/ attribute " + name);
  const Handle attribute = this->attribute(name);
  const Handle type = opened(H5Aget_type(attribute.id()), Handle::Kind::Datatype, where, "no type");
  if (H5Tget_class(type.id()) != H5T_STRING) fail(where, "not a string");
  if (H5Tis_variable_str(type.id()) > 0) {
    char* value = nullptr;
    if (H5Aread(attribute.id(), type.id(), &value) < 0) fail(where, "HDF5 failed to read it");
    const std::unique_ptr<char, herr_t (*)(void*)> owned(value, H5free_memory);
    return value ? std::string(value) : std::string();
  }
  std::string value(H5Tget_size(type.id()), '\0');
  if (H5Aread(attribute.id(), type.id(), value.data()) < 0) fail(where, "HDF5 failed to read it");
  return value.substr(0, value.find('\0'));
}

}  // namespace stc::h5
