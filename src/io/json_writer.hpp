#pragma once
// The ordered JSON object builder for summary.json (docs/interface.md), over nlohmann-json's
// ordered_json (kept out of this header). Members keep the order of add(), a key added twice is
// refused; strings are escaped (RFC 8259 §7); doubles are written in a shortest form that reads
// back to the same value; non-finite doubles, which JSON cannot express, as null.
#include <concepts>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace stc {

/// An already formatted JSON value (e.g. the scene's parameters as read), parsed and inserted in
/// its place, its members in their order. An empty or invalid text is refused.
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
  JsonObject();
  ~JsonObject();
  JsonObject(const JsonObject& other);
  JsonObject(JsonObject&& other) noexcept;
  JsonObject& operator=(const JsonObject& other);
  JsonObject& operator=(JsonObject&& other) noexcept;

  JsonObject& add(std::string key, std::string_view value);
  JsonObject& add(std::string key, const char* value);  ///< nullptr is written as null
  JsonObject& add(std::string key, double value);       ///< NaN and ±inf are written as null
  JsonObject& add(std::string key, bool value);
  JsonObject& add(std::string key, std::nullopt_t);
  JsonObject& add(std::string key, const JsonObject& value);
  JsonObject& add(std::string key, const std::vector<double>& values);
  JsonObject& add(std::string key, const std::vector<JsonObject>& values);  ///< an array of objects
  JsonObject& add(std::string key, const RawJson& value);

  template <detail::JsonInteger T>
  JsonObject& add(std::string key, T value) {
    if constexpr (std::is_signed_v<T>) return addSigned(std::move(key), static_cast<long long>(value));
    else return addUnsigned(std::move(key), static_cast<unsigned long long>(value));
  }

  /// The value, or null when empty (e.g. the error when no reference solution is known).
  template <typename T>
  JsonObject& add(std::string key, const std::optional<T>& value) {
    return value ? add(std::move(key), *value) : add(std::move(key), std::nullopt);
  }

  /// The document; indent > 0 puts one member per line (and a final line break), indent <= 0
  /// writes a single line.
  std::string str(int indent = 2) const;
  bool empty() const;

 private:
  struct Document;  ///< nlohmann::ordered_json
  std::unique_ptr<Document> document_;

  JsonObject& addSigned(std::string key, long long value);
  JsonObject& addUnsigned(std::string key, unsigned long long value);
  JsonObject& addDocument(std::string key, Document value);
};

/// `text` as a quoted JSON string: quote, backslash and control characters escaped
/// (\n, \t... or \u00XX); other bytes, UTF-8 included, are copied (invalid UTF-8: U+FFFD).
std::string jsonString(std::string_view text);
/// A shortest decimal that reads back (strtod) to exactly `value`; "null" if not finite.
std::string jsonNumber(double value);

}  // namespace stc
