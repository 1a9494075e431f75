#pragma once
// A file the input names does not exist (a scene file, a Gmsh mesh file). It is an InputError with
// the message any file that cannot be opened gets (the command line prints it and exits 1 alike),
// and it carries the path, so that a caller can tell "missing" from "unreadable": the Python module
// raises FileNotFoundError (errno ENOENT, the path as filename) for it (python/module.cpp).
#include <filesystem>
#include <string>
#include <utility>

#include "stcontact/core/input_error.hpp"

namespace stc {

class MissingFileError : public InputError {
 public:
  MissingFileError(const std::string& message, std::string path) : InputError(message), path_(std::move(path)) {}

  /// The path as the input named it.
  const std::string& path() const { return path_; }

  /// True when nothing exists at `file` (a missing folder on the way included); false for a file
  /// that exists but cannot be read, or whose folder cannot be searched.
  static bool isMissing(const std::filesystem::path& file) {
    std::error_code ec;
    return std::filesystem::status(file, ec).type() == std::filesystem::file_type::not_found;
  }

 private:
  std::string path_;
};

}  // namespace stc
