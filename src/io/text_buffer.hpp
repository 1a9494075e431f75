#pragma once
// Text of the large output files (contact.csv, the .vtu frames) built in memory and written in one
// piece. A std::ostream pays a sentry and a virtual call per inserted item and formats a double
// through vsnprintf; at 801 contact nodes and 201 instants these files hold 10⁷ numbers and their
// writing took longer than the solve. std::to_chars in the general format with precision p writes
// what printf's %.pg (and an ostream with precision p) writes, so the files are byte for byte those
// of the stream writers.
#include <charconv>
#include <ostream>
#include <string>
#include <string_view>

namespace stc {

class TextBuffer {
 public:
  /// %.{digits}g of `value` (nan, inf and -0 as printf writes them).
  TextBuffer& number(double value, int digits) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
    text_.append(buffer, result.ptr);
    return *this;
  }
  TextBuffer& integer(long long value) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    text_.append(buffer, result.ptr);
    return *this;
  }
  TextBuffer& text(std::string_view s) {
    text_.append(s);
    return *this;
  }
  TextBuffer& put(char c) {
    text_.push_back(c);
    return *this;
  }

  std::size_t size() const { return text_.size(); }
  const std::string& str() const { return text_; }
  /// Writes the text to `out` and empties the buffer (its capacity stays).
  void flushTo(std::ostream& out) {
    out.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

 private:
  std::string text_;
};

}  // namespace stc
