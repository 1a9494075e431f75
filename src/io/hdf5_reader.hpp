#pragma once
// Reading back what hdf5_file.hpp writes (libhdf5's C API, https://docs.hdfgroup.org/hdf5/v1_10/):
// a file opened read-only, its datasets of numbers as doubles (row-major, as HDF5 stores) and the
// root group's scalar attributes. An earlier run's solution.h5 is the user's input here, so every
// failure is an InputError naming the file and the object (a missing file a MissingFileError).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "stcontact/io/hdf5_file.hpp"

namespace stc::h5 {

/// A dataset read whole: its dimensions and its elements converted to double, row-major.
struct DoubleArray {
  std::vector<std::uint64_t> dims;
  std::vector<double> values;
};

class Reader {
 public:
  /// Opens `path` read-only; throws MissingFileError when nothing is there, InputError when it is not
  /// an HDF5 file HDF5 can open.
  explicit Reader(const std::filesystem::path& path);

  /// The dataset at `path` ("/interface/force"), whatever its numeric type.
  DoubleArray doubles(const std::string& path) const;
  /// Whether the root group has the attribute `name`.
  bool hasAttribute(const std::string& name) const;
  /// The root group's attribute `name` as a double (any numeric attribute), as a string (a string
  /// attribute, fixed or variable length).
  double number(const std::string& name) const;
  std::string text(const std::string& name) const;

  /// "file.h5:/path", for messages.
  std::string where(const std::string& path) const { return file_ + ":" + path; }

 private:
  Handle attribute(const std::string& name) const;  ///< the root group's, opened; InputError when absent

  std::string file_;
  Handle handle_;
};

}  // namespace stc::h5
