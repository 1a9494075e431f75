#include "stcontact/scene/detail/scene_errors.hpp"

#include <algorithm>

#include <charconv>
#include <cmath>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"

namespace stc::detail {

namespace {

/// True when `a` is `b` or lies inside it ("dirichlet[1].times[2]" inside "dirichlet[1]").
bool isWithin(std::string_view a, std::string_view b) {
  if (a.size() < b.size() || a.substr(0, b.size()) != b) return false;
  return a.size() == b.size() || a[b.size()] == '.' || a[b.size()] == '[';
}

/// Messages are one line: newlines and tabs (from toml++ or a user's string) become spaces.
std::string oneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  return text;
}

}  // namespace

std::string keyPath(std::string_view parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  std::string path(parent);
  path += '.';
  path += key;
  return path;
}

std::string indexPath(std::string_view parent, std::size_t index) {
  return std::string(parent) + "[" + std::to_string(index) + "]";
}

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string describeType(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

ErrorReporter::ErrorReporter(std::string file) : file_(std::move(file)) {
  if (file_.empty()) file_ = "<scene>";
}

void ErrorReporter::noteOverride(std::string path, std::string text) {
  overrides_.emplace_back(std::move(path), std::move(text));
}

std::string ErrorReporter::overrideNote(std::string_view path) const {
  // The latest override wins, as when they were applied.
  for (auto it = overrides_.rbegin(); it != overrides_.rend(); ++it) {
    if (isWithin(path, it->first) || isWithin(it->first, path)) {
      return " (from --set " + it->second + ")";
    }
  }
  return {};
}

void ErrorReporter::fail(std::string_view path, const std::string& message) const {
  throw InputError(oneLine(file_ + ": " + message + overrideNote(path)));
}

void ErrorReporter::wrongType(std::string_view path, std::string_view expected,
                              const toml::node& got) const {
  fail(path, "key '" + std::string(path) + "' must be " + std::string(expected) + ", got " +
                 describeType(got));
}

void ErrorReporter::outOfRange(std::string_view path, std::string_view value,
                               std::string_view rule) const {
  fail(path, "key '" + std::string(path) + "' = " + std::string(value) +
                 " is out of range: " + std::string(rule));
}

void ErrorReporter::missing(std::string_view path) const {
  fail(path, "missing required key '" + std::string(path) + "'");
}

void ErrorReporter::failFile(const std::string& message) const {
  throw InputError(oneLine(file_ + ": " + message));
}

void ErrorReporter::failMissingFile(const std::string& message) const {
  throw MissingFileError(oneLine(file_ + ": " + message), file_);
}

void ErrorReporter::failAt(std::size_t line, std::size_t column, const std::string& message) const {
  throw InputError(
      oneLine(file_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message));
}

void ErrorReporter::failAtOffset(std::string_view text, std::size_t offset, const std::string& message) const {
  const std::string_view before = text.substr(0, offset);
  const std::size_t line_start = before.rfind('\n') + 1;  // npos + 1 = 0 on the first line
  failAt(1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n')), offset - line_start + 1,
         message);
}

}  // namespace stc::detail
