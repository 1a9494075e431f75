#include "stcontact/scene/detail/array_value_guard.hpp"

#include <cstddef>
#include <vector>

namespace stc::detail {

namespace {

/// The index just past the string that starts at `i` (TOML 1.0 "String": "...", '...', """...""",
/// '''...''', backslash escapes in the basic ones); an unterminated one-line string ends at the
/// line's end, where the parser stops.
std::size_t endOfString(std::string_view text, std::size_t i) {
  const char quote = text[i];
  const bool multi_line = text.substr(i, 3) == std::string_view(quote == '"' ? "\"\"\"" : "'''");
  std::size_t k = i + (multi_line ? 3 : 1);
  while (k < text.size()) {
    if (quote == '"' && text[k] == '\\') k += 2;
    else if (!multi_line && text[k] == '\n') return k;
    else if (text[k] != quote) ++k;
    else if (!multi_line) return k + 1;
    else if (text.substr(k, 3) == std::string_view(quote == '"' ? "\"\"\"" : "'''")) {
      k += 3;
      while (k < text.size() && text[k] == quote) ++k;  // up to two more quotes belong to the text
      return k;
    } else ++k;
  }
  return text.size();
}

/// The value being read at the top level of a key/value line: its open arrays and inline tables.
class ValueScan {
 public:
  ValueScan(std::string_view text, const ErrorReporter& errors) : text_(text), errors_(errors) {}

  void run() {
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '#') {
        while (i_ < text_.size() && text_[i_] != '\n') ++i_;
      } else if (c == '"' || c == '\'') {
        i_ = endOfString(text_, i_);
        want_value_ = false;
      } else if (c == '\n') {
        ++i_;
        if (open_.empty()) want_value_ = false;  // a key/value line ends with its value
      } else {
        if (c != ' ' && c != '\t' && c != '\r' && !code(c)) return;
        ++i_;
      }
    }
  }

 private:
  /// One character outside strings and comments; false once the brackets stop matching.
  bool code(char c) {
    if (open_.empty()) {
      const bool opens = want_value_ && (c == '[' || c == '{');
      if (opens) open_.push_back(c);
      want_value_ = c == '=' || (opens && c == '[');
      return true;
    }
    const char top = open_.back();
    if (c == '}' && top == '[' && want_value_)
      errors_.failAtOffset(text_, i_, "TOML syntax error: expected a value or ']' in the array, saw '}'");
    if (c == '[' || c == '{') {
      open_.push_back(c);
      want_value_ = c == '[';
    } else if (c == ']' || c == '}') {
      if ((c == ']') != (top == '[')) return false;
      open_.pop_back();
      want_value_ = false;
    } else {
      want_value_ = c == ',' && top == '[';
    }
    return true;
  }

  std::string_view text_;
  const ErrorReporter& errors_;
  std::vector<char> open_;   ///< '[' and '{' not yet closed
  bool want_value_ = false;  ///< after '=' at the top level; after '[' or ',' in an array
  std::size_t i_ = 0;
};

}  // namespace

void refuseBraceForArrayValue(std::string_view text, const ErrorReporter& errors) {
  ValueScan(text, errors).run();
}

}  // namespace stc::detail
