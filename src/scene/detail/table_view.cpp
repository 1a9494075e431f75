#include "stcontact/scene/detail/table_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace stc::detail {

std::string asString(const toml::node& node, std::string_view path, const ErrorReporter& errors) {
  const auto* value = node.as_string();
  if (value == nullptr) errors.wrongType(path, "a string", node);
  return value->get();
}

double asNumber(const toml::node& node, std::string_view path, const ErrorReporter& errors) {
  double number = 0.0;
  if (const auto* integer = node.as_integer()) {
    number = static_cast<double>(integer->get());
  } else if (const auto* floating = node.as_floating_point()) {
    number = floating->get();
  } else {
    errors.wrongType(path, "a number", node);
  }
  if (!std::isfinite(number)) {
    errors.fail(path, "key '" + std::string(path) + "' = " + formatNumber(number) +
                          " is not a finite number");
  }
  return number;
}

int asInt(const toml::node& node, std::string_view path, const ErrorReporter& errors) {
  const auto* integer = node.as_integer();
  if (integer == nullptr) errors.wrongType(path, "an integer", node);
  const std::int64_t value = integer->get();
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
    errors.outOfRange(path, std::to_string(value), "must fit in a 32-bit integer");
  }
  return static_cast<int>(value);
}

bool asBool(const toml::node& node, std::string_view path, const ErrorReporter& errors) {
  const auto* boolean = node.as_boolean();
  if (boolean == nullptr) errors.wrongType(path, "a boolean", node);
  return boolean->get();
}

std::vector<double> asNumbers(const toml::node& node, std::string_view path,
                              const ErrorReporter& errors) {
  const auto* array = node.as_array();
  if (array == nullptr) errors.wrongType(path, "an array of numbers", node);
  std::vector<double> numbers;
  numbers.reserve(array->size());
  for (std::size_t i = 0; i < array->size(); ++i) {
    numbers.push_back(asNumber(*array->get(i), indexPath(path, i), errors));
  }
  return numbers;
}

const toml::table& asTable(const toml::node& node, std::string_view path,
                           const ErrorReporter& errors) {
  const auto* table = node.as_table();
  if (table == nullptr) errors.wrongType(path, "a table", node);
  return *table;
}

TableView::TableView(const toml::table& table, std::string path, const ErrorReporter& errors,
                     std::initializer_list<std::string_view> keys)
    : TableView(table, std::move(path), errors, std::vector<std::string_view>(keys)) {}

TableView::TableView(const toml::table& table, std::string path, const ErrorReporter& errors,
                     const std::vector<std::string_view>& keys)
    : table_(&table), path_(std::move(path)), errors_(&errors) {
  rejectUnknownKeys(keys);
}

namespace {

// Keys renamed since an earlier version, named in the refusal (docs/changelog.md, 0.4.0).
constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kRenamedKeys = {{
    {"output.vtu", "output.frames"},
    {"output.vtu_stride", "output.frame_stride"},
    {"output.vtu_precision", "output.field_precision"},
}};

std::string renamedTo(std::string_view path) {
  for (const auto& [old_name, new_name] : kRenamedKeys)
    if (path == old_name) return "; renamed '" + std::string(new_name) + "' in version 0.4";
  return "";
}

}  // namespace

void TableView::rejectUnknownKeys(const std::vector<std::string_view>& keys) const {
  for (const auto& [key, node] : *table_) {
    if (std::find(keys.begin(), keys.end(), key.str()) != keys.end()) continue;
    std::string allowed;
    for (const auto known : keys) {
      allowed += (allowed.empty() ? "" : ", ") + std::string(known);
    }
    const std::string where = path_.empty() ? "at the top level" : "in [" + path_ + "]";
    const std::string path = keyPath(key.str());
    errors_->fail(path, "unknown key '" + path + "' (allowed " + where + ": " + allowed + ")" + renamedTo(path));
  }
}

std::string TableView::keyPath(std::string_view key) const { return detail::keyPath(path_, key); }

const toml::node& TableView::require(std::string_view key) const {
  const toml::node* node = find(key);
  if (node == nullptr) errors_->missing(keyPath(key));
  return *node;
}

std::string TableView::requiredString(std::string_view key) const {
  return asString(require(key), keyPath(key), *errors_);
}

std::optional<std::string> TableView::optionalString(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return requiredString(key);
}

double TableView::requiredNumber(std::string_view key) const {
  return asNumber(require(key), keyPath(key), *errors_);
}

std::optional<double> TableView::optionalNumber(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return requiredNumber(key);
}

int TableView::requiredInt(std::string_view key) const {
  return asInt(require(key), keyPath(key), *errors_);
}

std::optional<int> TableView::optionalInt(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return requiredInt(key);
}

std::optional<bool> TableView::optionalBool(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return asBool(require(key), keyPath(key), *errors_);
}

std::vector<double> TableView::requiredNumbers(std::string_view key) const {
  return asNumbers(require(key), keyPath(key), *errors_);
}

TableView TableView::requiredTable(std::string_view key,
                                   std::initializer_list<std::string_view> keys) const {
  const std::string path = keyPath(key);
  return TableView(asTable(require(key), path, *errors_), path, *errors_, keys);
}

std::optional<TableView> TableView::optionalTable(
    std::string_view key, std::initializer_list<std::string_view> keys) const {
  if (!has(key)) return std::nullopt;
  return requiredTable(key, keys);
}

std::optional<TableView> TableView::optionalTable(std::string_view key,
                                                  const std::vector<std::string_view>& keys) const {
  if (!has(key)) return std::nullopt;
  const std::string path = keyPath(key);
  return TableView(asTable(require(key), path, *errors_), path, *errors_, keys);
}

}  // namespace stc::detail
