#include <iostream>
#include <set>

#include "stcontact/cli/commands.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace stc::cli {

Scene loadScene(const std::string& file, const std::vector<std::string>& overrides) {
  Scene scene = readScene(file, overrides);
  static std::set<std::string> printed;  // a sweep reads the scene once per value
  for (const std::string& warning : scene.warnings)
    if (printed.insert(warning).second) std::cerr << "warning: " << file << ": " << warning << std::endl;
  return scene;
}

}  // namespace stc::cli
