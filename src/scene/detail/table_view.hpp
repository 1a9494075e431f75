#pragma once
// Checked, typed access to one TOML table of a scene. Construction rejects keys outside the
// table's schema; each getter names the key by its full dotted path and throws InputError
// (through ErrorReporter) for a missing required key, a wrong type or a non-finite number.
#include <toml++/toml.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stcontact/scene/detail/scene_errors.hpp"

namespace stc::detail {

// Conversions of one node; `path` names it in messages.
std::string asString(const toml::node& node, std::string_view path, const ErrorReporter& errors);
/// An integer or a float (integers are accepted where a float is expected), finite.
double asNumber(const toml::node& node, std::string_view path, const ErrorReporter& errors);
/// An integer (a float is a type error) that fits in `int`.
int asInt(const toml::node& node, std::string_view path, const ErrorReporter& errors);
bool asBool(const toml::node& node, std::string_view path, const ErrorReporter& errors);
/// An array of finite numbers.
std::vector<double> asNumbers(const toml::node& node, std::string_view path,
                              const ErrorReporter& errors);
const toml::table& asTable(const toml::node& node, std::string_view path,
                           const ErrorReporter& errors);

class TableView {
 public:
  /// `path` is the table's dotted path ("" for the document); `keys` its allowed keys.
  TableView(const toml::table& table, std::string path, const ErrorReporter& errors,
            std::initializer_list<std::string_view> keys);
  TableView(const toml::table& table, std::string path, const ErrorReporter& errors,
            const std::vector<std::string_view>& keys);

  const std::string& path() const { return path_; }
  const ErrorReporter& errors() const { return *errors_; }
  /// Full dotted path of `key` in this table.
  std::string keyPath(std::string_view key) const;
  bool has(std::string_view key) const { return table_->contains(key); }
  /// The node, or nullptr when absent.
  const toml::node* find(std::string_view key) const { return table_->get(key); }
  /// The node; "missing required key" when absent.
  const toml::node& require(std::string_view key) const;

  std::string requiredString(std::string_view key) const;
  std::optional<std::string> optionalString(std::string_view key) const;
  double requiredNumber(std::string_view key) const;
  std::optional<double> optionalNumber(std::string_view key) const;
  int requiredInt(std::string_view key) const;
  std::optional<int> optionalInt(std::string_view key) const;
  std::optional<bool> optionalBool(std::string_view key) const;
  std::vector<double> requiredNumbers(std::string_view key) const;

  /// A sub-table with its own schema; "missing required key" when absent.
  TableView requiredTable(std::string_view key, std::initializer_list<std::string_view> keys) const;
  /// A sub-table with its own schema, or nullopt when absent.
  std::optional<TableView> optionalTable(std::string_view key,
                                         std::initializer_list<std::string_view> keys) const;
  std::optional<TableView> optionalTable(std::string_view key, const std::vector<std::string_view>& keys) const;

 private:
  void rejectUnknownKeys(const std::vector<std::string_view>& keys) const;

  const toml::table* table_;
  std::string path_;
  const ErrorReporter* errors_;
};

}  // namespace stc::detail
