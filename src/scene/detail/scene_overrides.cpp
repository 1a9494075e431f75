#include "stcontact/scene/detail/scene_overrides.hpp"

#include "stcontact/scene/detail/guarded_parse.hpp"

#include <cctype>
#include <charconv>
#include <optional>
#include <string_view>

namespace stc::detail {

namespace {

/// One step of an override path: a key of a table or an index into an array.
struct Step {
  std::string key;
  std::optional<std::size_t> index;
};

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

bool isBareKeyChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

/// Parses "a.b[2].c" into steps; nullopt when malformed (an index too large for size_t too).
std::optional<std::vector<Step>> parsePath(std::string_view text) {
  std::vector<Step> steps;
  std::size_t i = 0;
  while (true) {
    const std::size_t start = i;
    while (i < text.size() && isBareKeyChar(text[i])) ++i;
    if (i == start) return std::nullopt;
    steps.push_back({std::string(text.substr(start, i - start)), std::nullopt});
    while (i < text.size() && text[i] == '[') {
      const std::size_t digits = ++i;
      while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) != 0) ++i;
      if (i == digits || i >= text.size() || text[i] != ']') return std::nullopt;
      std::size_t index = 0;  // from_chars, not stoul: an index past size_t is no exception
      if (std::from_chars(text.data() + digits, text.data() + i, index).ec != std::errc())
        return std::nullopt;
      steps.push_back({{}, index});
      ++i;
    }
    if (i == text.size()) return steps;
    if (text[i] != '.') return std::nullopt;
    ++i;
  }
}

/// The canonical text of a path, as the reader names keys ("dirichlet[1].values").
std::string pathText(const std::vector<Step>& steps, std::size_t count) {
  std::string text;
  for (std::size_t i = 0; i < count; ++i) {
    text = steps[i].index ? indexPath(text, *steps[i].index) : keyPath(text, steps[i].key);
  }
  return text;
}

/// The value as TOML ("v = <text>", behind the guards of guarded_parse.hpp), else the text as a string.
toml::table parseValue(std::string_view text) {
  std::optional<toml::table> parsed = tryParseGuarded("v = " + std::string(text));
  if (parsed && parsed->size() == 1 && parsed->contains("v")) return *std::move(parsed);
  toml::table bare;
  bare.insert("v", std::string(text));
  return bare;
}

/// 'text' for messages. Built by appending: "'" + std::string&& trips GCC 12's -Wrestrict false
/// positive (bug 105329).
std::string quoted(std::string_view text) {
  std::string q(1, '\'');
  q += text;
  q += '\'';
  return q;
}

/// Context of one override, for its messages.
struct Override {
  const std::string& text;
  const ErrorReporter& errors;
  [[noreturn]] void fail(const std::string& rule) const {
    errors.failFile("--set " + text + ": " + rule);
  }
};

/// Walks to the node that holds the last step, creating missing tables on the way.
toml::node& walkToParent(toml::table& root, const std::vector<Step>& steps, const Override& o) {
  toml::node* node = &root;
  for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
    const std::string here = pathText(steps, i + 1);
    if (steps[i].index) {
      auto* array = node->as_array();
      if (array == nullptr) o.fail(quoted(pathText(steps, i)) + " is not an array");
      if (*steps[i].index >= array->size()) {
        o.fail(quoted(pathText(steps, i)) + " has " + std::to_string(array->size()) +
               " entries, so '" + here + "' does not exist");
      }
      node = array->get(*steps[i].index);
      continue;
    }
    auto* table = node->as_table();
    if (table == nullptr) o.fail(quoted(pathText(steps, i)) + " is not a table");
    if (!table->contains(steps[i].key)) {
      if (steps[i + 1].index) o.fail(quoted(here) + " does not exist");
      table->insert(steps[i].key, toml::table{});
    }
    node = table->get(steps[i].key);
  }
  return *node;
}

/// Stores `value` at the last step under `parent`.
void store(toml::node& parent, const std::vector<Step>& steps, const toml::node& value,
           const Override& o) {
  const Step& last = steps.back();
  const std::string owner = pathText(steps, steps.size() - 1);
  value.visit([&](const auto& v) {
    if (last.index) {
      auto* array = parent.as_array();
      if (array == nullptr) o.fail(quoted(owner) + " is not an array");
      if (*last.index >= array->size()) {
        o.fail(quoted(owner) + " has " + std::to_string(array->size()) + " entries, so '" +
               pathText(steps, steps.size()) + "' does not exist");
      }
      array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(*last.index), v);
    } else {
      auto* table = parent.as_table();
      if (table == nullptr) o.fail(quoted(owner) + " is not a table");
      table->insert_or_assign(last.key, v);
    }
  });
}

void applyOverride(toml::table& scene, const std::string& text, ErrorReporter& errors) {
  const Override o{text, errors};
  const auto equals = text.find('=');
  if (equals == std::string::npos) o.fail("expected KEY=VALUE (e.g. contact.friction=0.3)");
  const auto steps = parsePath(trim(std::string_view(text).substr(0, equals)));
  if (!steps) o.fail("malformed key (expected name, section.key or section[i].key)");
  const std::string_view valueText = trim(std::string_view(text).substr(equals + 1));
  if (valueText.empty()) o.fail("missing value after '='");
  if (valueText.find_first_of("\r\n") != std::string_view::npos) o.fail("value has a newline");
  const toml::table parsed = parseValue(valueText);
  const toml::node& value = *parsed.get("v");
  if (value.is_table()) o.fail("the value must be a scalar or an array, not a table");
  store(walkToParent(scene, *steps, o), *steps, value, o);
  errors.noteOverride(pathText(*steps, steps->size()), text);
}

}  // namespace

void applyOverrides(toml::table& scene, const std::vector<std::string>& overrides,
                    ErrorReporter& errors) {
  for (const auto& text : overrides) applyOverride(scene, text, errors);
}

}  // namespace stc::detail
