#include "stcontact/scene/detail/non_ascii_guard.hpp"

#include <cstddef>
#include <string>

namespace stc::detail {

namespace {

constexpr std::string_view kBom = "\xEF\xBB\xBF";  // UTF-8 byte order mark; toml++ skips it

bool isAscii(char c) { return static_cast<unsigned char>(c) < 0x80; }

/// A left-to-right scan of TOML's lexical states: enough to tell strings and comments apart
/// from the rest (TOML 1.0 "Comment", "String").
class Scanner {
 public:
  Scanner(std::string_view text, const ErrorReporter& errors) : text_(text), errors_(errors) {}

  void run() {
    if (text_.substr(0, kBom.size()) == kBom) i_ = kBom.size();
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '#') skipTo('\n');
      else if (startsWith("\"\"\"")) multiLineString('"');
      else if (startsWith("'''")) multiLineString('\'');
      else if (c == '"' || c == '\'') string(c);
      else if (!isAscii(c)) fail("a non-ASCII character is allowed only in a string or a comment");
      else step();
    }
  }

 private:
  bool startsWith(std::string_view s) const { return text_.substr(i_, s.size()) == s; }
  void step() { ++i_; }
  void skipTo(char end) {
    while (i_ < text_.size() && text_[i_] != end) step();
  }
  /// After a backslash in a basic string: escapes are ASCII letters, never a non-ASCII byte.
  void escape() {
    step();
    if (i_ < text_.size() && !isAscii(text_[i_])) fail("a backslash must not escape a non-ASCII character");
  }
  /// "..." or '...' on one line (an unterminated one ends at the line's end, where toml++ stops).
  void string(char quote) {
    step();
    while (i_ < text_.size() && text_[i_] != quote && text_[i_] != '\n') {
      if (quote == '"' && text_[i_] == '\\') escape();  // then step() takes the escaped character
      if (i_ < text_.size() && text_[i_] != '\n') step();
    }
    if (i_ < text_.size() && text_[i_] == quote) step();
  }
  /// """...""" or '''...''': up to two more quotes before the closing three belong to the text.
  void multiLineString(char quote) {
    const std::string close(3, quote);
    for (int k = 0; k < 3; ++k) step();
    while (i_ < text_.size() && !startsWith(close)) {
      if (quote == '"' && text_[i_] == '\\') continuedLine();
      else step();
    }
    for (int k = 0; k < 5 && i_ < text_.size() && text_[i_] == quote; ++k) step();
  }
  /// A backslash in """...""": an escape, or a line-ending backslash whose next line may not
  /// start with a non-ASCII character (toml++ 3.3.0 asks whether it is whitespace).
  void continuedLine() {
    constexpr std::string_view kBlank = " \t\r\n";
    escape();
    if (i_ >= text_.size()) return;
    if (kBlank.find(text_[i_]) == std::string_view::npos) return step();  // \" \\ \n \u...
    while (i_ < text_.size() && kBlank.find(text_[i_]) != std::string_view::npos) step();
    if (i_ < text_.size() && !isAscii(text_[i_]))
      fail("a line continued with a backslash must not start with a non-ASCII character (write it "
           "on the line before, or as a \\u escape)");
  }
  [[noreturn]] void fail(const std::string& rule) const {
    errors_.failAtOffset(text_, i_, "TOML syntax error: " + rule);
  }

  std::string_view text_;
  const ErrorReporter& errors_;
  std::size_t i_ = 0;
};

}  // namespace

void refuseMisplacedNonAscii(std::string_view text, const ErrorReporter& errors) {
  Scanner(text, errors).run();
}

std::string asciiStandIn(std::string_view text) {
  std::string ascii(text);
  const std::size_t kept = ascii.starts_with(kBom) ? kBom.size() : 0;  // toml++ skips it untested
  for (std::size_t i = kept; i < ascii.size(); ++i)
    if (!isAscii(ascii[i])) ascii[i] = '~';
  return ascii;
}

}  // namespace stc::detail
