#pragma once
// The module's scene: a TOML text, the file it came from (named in messages, the folder of a
// relative mesh path) and `--set` overrides, validated on construction by stc::parseScene, the
// command line's own reader, so that a Python dict and a file go through every check alike and a
// bad value gives the command line's message. The assembled Problem is built on first use.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene.hpp"

namespace stc::python {

class SceneHandle {
 public:
  /// Reads `file` as `stcontact` does (its messages for a missing or unreadable file).
  static SceneHandle fromFile(const std::filesystem::path& file, std::vector<std::string> overrides);
  /// Parses `text` as if read from `source`.
  static SceneHandle fromText(std::string text, std::filesystem::path source, std::vector<std::string> overrides);

  const Scene& scene() const { return *scene_; }
  const std::string& text() const { return *text_; }
  const std::filesystem::path& source() const { return source_; }
  const std::vector<std::string>& overrides() const { return overrides_; }

  /// The same text with `extra` overrides after this one's (a solve's sets and options), validated
  /// anew; without any, this scene itself (its problem, once built, is shared).
  SceneHandle withOverrides(const std::vector<std::string>& extra) const;

  /// The assembled problem (InputError for what needs the mesh: boundary names, penetration...).
  /// Built on the first call, with the interpreter's lock held, then shared with the results.
  std::shared_ptr<const Problem> problem() const;

 private:
  SceneHandle(std::shared_ptr<const std::string> text, std::filesystem::path source,
              std::vector<std::string> overrides);

  std::shared_ptr<const std::string> text_;
  std::filesystem::path source_;
  std::vector<std::string> overrides_;
  std::shared_ptr<const Scene> scene_;
  mutable std::shared_ptr<const Problem> problem_;
};

}  // namespace stc::python
