#pragma once
// A result file or folder could not be written (missing folder, full disk, a path through a
// regular file...). Messages name the path and the system's reason (strerror).
#include <stdexcept>
#include <string>

namespace stc {

class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace stc
