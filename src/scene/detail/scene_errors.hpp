#pragma once
// The scene reader's error messages: "FILE: <what>", one line, naming the key by its full dotted
// path ("dirichlet[1].times") and the rule broken; keys written by `--set` say so.
#include <toml++/toml.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stc::detail {

/// "section.key", or "key" at the top level.
std::string keyPath(std::string_view parent, std::string_view key);
/// "parent[index]".
std::string indexPath(std::string_view parent, std::size_t index);
/// Shortest text that reads back to `value` ("0.5", "1e-06", "nan", "-inf").
std::string formatNumber(double value);
/// "a string", "an integer", "a float", "a table", ... for "got ..." in messages.
std::string describeType(const toml::node& node);

/// Builds and throws InputError for one scene file.
class ErrorReporter {
 public:
  explicit ErrorReporter(std::string file);

  /// Records that `path` was written by `--set <text>`: errors about it (or inside it) say so.
  void noteOverride(std::string path, std::string text);

  /// Throws "FILE: <message>" (plus the override note when `path` came from --set).
  [[noreturn]] void fail(std::string_view path, const std::string& message) const;
  /// "key 'P' must be <expected>, got <type of node>".
  [[noreturn]] void wrongType(std::string_view path, std::string_view expected,
                              const toml::node& got) const;
  /// "key 'P' = <value> is out of range: <rule>".
  [[noreturn]] void outOfRange(std::string_view path, std::string_view value,
                               std::string_view rule) const;
  /// "missing required key 'P'".
  [[noreturn]] void missing(std::string_view path) const;
  /// Throws "FILE: <message>" about the file as a whole (I/O, --set syntax).
  [[noreturn]] void failFile(const std::string& message) const;
  /// The same as a MissingFileError: nothing exists at FILE.
  [[noreturn]] void failMissingFile(const std::string& message) const;
  /// Throws "FILE:LINE:COLUMN: <message>" (TOML syntax errors).
  [[noreturn]] void failAt(std::size_t line, std::size_t column, const std::string& message) const;
  /// The same at byte `offset` of `text`: line and column (in bytes, from 1) counted from it.
  [[noreturn]] void failAtOffset(std::string_view text, std::size_t offset, const std::string& message) const;

  const std::string& file() const { return file_; }

 private:
  std::string overrideNote(std::string_view path) const;

  std::string file_;
  std::vector<std::pair<std::string, std::string>> overrides_;  ///< (path, --set text)
};

}  // namespace stc::detail
