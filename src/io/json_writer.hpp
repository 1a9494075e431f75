#pragma once
// A small ordered JSON object builder for summary.json (docs/interface.md). Members keep the order of
// add(); strings are escaped (RFC 8259 §7); doubles are written in the shortest form that reads
// back to the same value (std::to_chars); non-finite doubles, which JSON cannot express, as null.
#include <concepts>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace stc {

/// An already formatted JSON value, inserted verbatim (e.g. the scene's parameters as read).
/// The caller vouches for its validity; only an empty text is rejected.
struct RawJson {
  std::string text;
};

namespace detail {
/// Any integer type except bool and the character types (a char is rarely meant as a number).
template <typename T>
concept JsonInteger = std::integral<T> && !std::same_as<T, bool> && !std::same_as<T, char> &&
                      !std::same_as<T, wchar_t> && !std::same_as<T, char8_t> &&
                      !std::same_as<T, char16_t> && !std::same_as<T, char32_t>;
}  // namespace detail

class JsonObject {
 public:
  JsonObject& add(std::string key, std::string_view value);
  JsonObject& add(std::string key, const char* value);  ///< nullptr is written as null
  JsonObject& add(std::string key, double value);       ///< NaN and ±inf are written as null
  JsonObject& add(std::string key, bool value);
  JsonObject& add(std::string key, std::nullopt_t);
  JsonObject& add(std::string key, JsonObject value);
  JsonObject& add(std::string key, const std::vector<double>& values);
  JsonObject& add(std::string key, RawJson value);

  template <detail::JsonInteger T>
  JsonObject& add(std::string key, T value) {
    return addText(std::move(key), std::to_string(value));
  }

  /// The value, or null when empty (e.g. the error when no reference solution is known).
  template <typename T>
  JsonObject& add(std::string key, const std::optional<T>& value) {
    return value ? add(std::move(key), *value) : add(std::move(key), std::nullopt);
  }

  /// The document; indent > 0 puts one member per line, indent <= 0 writes a single line.
  std::string str(int indent = 2) const;
  bool empty() const { return members_.empty(); }

 private:
  struct Member {
    std::string key;
    std::string text;                          ///< the rendered value, unless `object` is set
    std::shared_ptr<const JsonObject> object;  ///< a nested object, rendered at its depth
  };
  std::vector<Member> members_;

  JsonObject& addText(std::string key, std::string text);
  void write(std::string& out, int indent, int depth) const;
};

/// `text` as a quoted JSON string: quote, backslash and control characters escaped
/// (\n, \t... or \u00XX); other bytes, UTF-8 included, are copied.
std::string jsonString(std::string_view text);
/// The shortest decimal that reads back (strtod) to exactly `value`; "null" if not finite.
std::string jsonNumber(double value);

}  // namespace stc
