#pragma once
// Bad input (scene, mesh, options): the command line maps it to exit status 1 and prints
// its message after "error: ". Messages name the file, key or entity and the rule broken.
#include <stdexcept>
#include <string>

namespace stc {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace stc
