#pragma once
// How an options struct declares its fields, once (docs/architecture.md, "Where an option lives"):
// the member's in-class initialiser is its default, its comment its documentation, and the struct's
//   template <class Self, class Visit> static void fields(Self& o, Visit&& visit)
// lists it with its key and the range it must lie in:
//   visit("pre_relaxations", o.pre_relaxations, atLeast(1));
// A field set from the library only (no scene key) says so: visit(..., Exposure::Library).
// Two walks read the list, so the range is checked, and its rule worded, in one place:
//   - validate() (validateFields below): InputError "<owner> option <key> = <value>: <rule>";
//   - the scene reader (src/scene/scene_reader.cpp): each key of [solver] read into the member and
//     checked against the same range, its error naming the file and the key.
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "stcontact/core/input_error.hpp"

namespace stc {

/// Whether a field is a key of the scene's [solver] table or is set from the library only.
enum class Exposure { SceneKey, Library };

/// The numbers an option accepts: low <= x <= high, either end strict, or the one value `off` that
/// turns the option off; `rule` says it as the messages print it ("must be >= 1"). NaN never holds.
struct Range {
  double low;
  double high;
  bool low_strict = false;
  bool high_strict = false;
  std::optional<double> off;
  std::string rule;

  bool holds(double x) const;
};

Range atLeast(int n);      ///< x >= n, finite: "must be >= n"
Range positive();          ///< x > 0, finite: "must be > 0"
Range inOpenUnit();        ///< 0 < x < 1: "must be in (0, 1)"
Range inUnitHalfOpen();    ///< 0 < x <= 1: "must be in (0, 1]"
Range inUnitClosed();      ///< 0 <= x <= 1: "must be in [0, 1]"
Range offOrAtLeast(int n); ///< 0 or x >= n: "must be 0 (off) or >= n"
Range offOrInOpenUnit();   ///< 0 or 0 < x < 1: "must be 0 (off) or in (0, 1)"
Range anyFlag();           ///< a boolean: no range

/// The names a keyword option takes, in the order messages list them.
template <class E>
using Keywords = std::span<const std::pair<std::string_view, E>>;

/// The name `names` gives `value` ("unknown" for a value it lists not).
template <class E>
constexpr std::string_view keywordOf(Keywords<E> names, E value) {
  for (const auto& [name, e] : names)
    if (e == value) return name;
  return "unknown";
}

/// The check of validate(): each field against its range.
class FieldCheck {
 public:
  explicit FieldCheck(const char* owner) : owner_(owner) {}
  void operator()(const char* key, int value, const Range& range, Exposure = Exposure::SceneKey) const;
  void operator()(const char* key, double value, const Range& range, Exposure = Exposure::SceneKey) const;
  template <class T>
  void operator()(const char* key, const std::optional<T>& value, const Range& range,
                  Exposure exposure = Exposure::SceneKey) const {
    if (value) (*this)(key, *value, range, exposure);
  }
  void operator()(const char*, bool, const Range&, Exposure = Exposure::SceneKey) const {}
  template <class E>
  void operator()(const char*, E, Keywords<E>, Exposure = Exposure::SceneKey) const {}

 private:
  const char* owner_;
};

/// Throws InputError "<owner> option <key> = <value>: <rule>" for the first field out of its range.
template <class Options>
void validateFields(const Options& options, const char* owner) {
  Options::fields(options, FieldCheck(owner));
}

/// A rule over several fields (validate() after validateFields): InputError
/// "<owner> option <what> = <value>: <rule>" unless `ok`.
void requireOption(bool ok, const char* owner, const char* what, int value, const char* rule);

}  // namespace stc
