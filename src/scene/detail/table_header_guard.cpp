#include "stcontact/scene/detail/table_header_guard.hpp"

#include <toml++/toml.h>

#include <cstddef>
#include <string>

namespace stc::detail {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

/// A character that starts a key: bare (A-Z a-z 0-9 _ -) or quoted (TOML 1.0 "Keys").
bool startsKey(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '"' || c == '\'';
}

/// "'c'" for a printable character, else what it is ("the end of the line", "byte 0x80").
std::string describe(char c) {
  if (c == '\n' || c == '\r') return "the end of the line";
  const auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x20 && byte < 0x7f) return {'\'', c, '\''};
  constexpr char kHex[] = "0123456789abcdef";
  return std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 0xf];
}

std::size_t skipBlanks(std::string_view text, std::size_t i) {
  while (i < text.size() && isBlank(text[i])) ++i;
  return i;
}

/// Where toml++ would call parse_key() if the line starting at `begin` is a table header ("[" or
/// "[[", each followed by optional blanks), or npos when the line is no header or its key start
/// is one toml++ handles (a key character, "]", the end of the text, "[ [" which it refuses).
std::size_t unsafeKeyStart(std::string_view text, std::size_t begin) {
  std::size_t i = skipBlanks(text, begin);
  if (i >= text.size() || text[i] != '[') return std::string_view::npos;
  const std::size_t open = i + 1;
  i = skipBlanks(text, open);
  if (i < text.size() && text[i] == '[') {
    if (i > open) return std::string_view::npos;  // "[ [": toml++'s own error
    i = skipBlanks(text, i + 1);
  }
  if (i >= text.size() || text[i] == ']' || startsKey(text[i])) return std::string_view::npos;
  return i;
}

/// True when `prefix` parses as TOML on its own. For a prefix that ends where a line begins, it
/// means toml++ reaches that line at the top level of the document, so a '[' there opens a table
/// header; otherwise the line lies inside a multi-line string or array, or an error before it
/// stops the parser first.
bool parsesAlone(std::string_view prefix) {
  try {
    static_cast<void>(toml::parse(prefix));  // only whether it throws matters
    return true;
  } catch (const toml::parse_error&) {
    return false;
  }
}

}  // namespace

void refuseMalformedTableHeaders(std::string_view text, const ErrorReporter& errors) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";  // toml++ skips it
  std::size_t begin = text.substr(0, kBom.size()) == kBom ? kBom.size() : 0;
  for (std::size_t line = 1; begin <= text.size(); ++line) {
    const std::size_t key = unsafeKeyStart(text, begin);
    if (key != std::string_view::npos && parsesAlone(text.substr(0, begin))) {
      errors.failAt(line, key - begin + 1,
                    "TOML syntax error: a table name cannot start with " + describe(text[key]) +
                        " (expected a bare or quoted key)");
    }
    const std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) break;
    begin = end + 1;
  }
}

}  // namespace stc::detail
