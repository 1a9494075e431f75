#include "stcontact/python/scene_handle.hpp"

#include <fstream>
#include <sstream>

#include "stcontact/scene/scene_reader.hpp"

namespace stc::python {

SceneHandle::SceneHandle(std::shared_ptr<const std::string> text, std::filesystem::path source,
                         std::vector<std::string> overrides)
    : text_(std::move(text)), source_(std::move(source)), overrides_(std::move(overrides)) {
  scene_ = std::make_shared<const Scene>(parseScene(*text_, source_, overrides_));
}

SceneHandle SceneHandle::fromFile(const std::filesystem::path& file, std::vector<std::string> overrides) {
  readScene(file, overrides);  // the command line's checks and messages, the file's own included
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return SceneHandle(std::make_shared<const std::string>(text.str()), file, std::move(overrides));
}

SceneHandle SceneHandle::fromText(std::string text, std::filesystem::path source, std::vector<std::string> overrides) {
  return SceneHandle(std::make_shared<const std::string>(std::move(text)), std::move(source), std::move(overrides));
}

SceneHandle SceneHandle::withOverrides(const std::vector<std::string>& extra) const {
  if (extra.empty()) return *this;
  std::vector<std::string> all = overrides_;
  all.insert(all.end(), extra.begin(), extra.end());
  return SceneHandle(text_, source_, std::move(all));
}

std::shared_ptr<const Problem> SceneHandle::problem() const {
  if (!problem_) problem_ = std::make_shared<const Problem>(buildProblem(*scene_));
  return problem_;
}

}  // namespace stc::python
