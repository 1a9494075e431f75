#include "stcontact/scene/detail/guarded_parse.hpp"

#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/scene/detail/array_value_guard.hpp"
#include "stcontact/scene/detail/non_ascii_guard.hpp"
#include "stcontact/scene/detail/table_header_guard.hpp"

namespace stc::detail {

namespace {

/// toml::parse; a syntax error becomes "FILE:LINE:COLUMN: TOML syntax error: ..." on one line.
toml::table parseOrFail(std::string_view text, const ErrorReporter& errors, const std::string& note) {
  try {
    return toml::parse(text, std::string_view(errors.file()));
  } catch (const toml::parse_error& error) {
    const auto& begin = error.source().begin;
    errors.failAt(begin.line, begin.column, "TOML syntax error: " + std::string(error.description()) + note);
  }
}

}  // namespace

// Misplaced non-ASCII characters are refused first; a '}' where an array expects a value, then
// malformed table headers are found in the all-ASCII stand-in (same offsets). The header guard
// comes last because it parses prefixes of the text: they must meet none of the other defects
// (fuzz finding: a prefix holding "[0.0, 2.7,}" reached toml++ from the header guard). A text with
// non-ASCII characters reaches the parser only once its stand-in has parsed.
// From toml++ 3.4 on (its version macros, toml++/impl/version.h), whose parser has these defects
// fixed, the text goes to the parser directly.
toml::table parseGuarded(std::string_view text, const ErrorReporter& errors) {
#if TOML_LIB_MAJOR > 3 || (TOML_LIB_MAJOR == 3 && TOML_LIB_MINOR >= 4)
  return parseOrFail(text, errors, "");
#else
  refuseMisplacedNonAscii(text, errors);
  const std::string ascii = asciiStandIn(text);
  refuseBraceForArrayValue(ascii, errors);
  refuseMalformedTableHeaders(ascii, errors);
  if (ascii != text) parseOrFail(ascii, errors, " (each byte of a non-ASCII character read as '~')");
  return parseOrFail(text, errors, "");
#endif
}

std::optional<toml::table> tryParseGuarded(std::string_view text) {
  try {
    return parseGuarded(text, ErrorReporter("value"));
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace stc::detail
