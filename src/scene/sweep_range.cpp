#include "stcontact/scene/sweep_range.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>

#include "stcontact/core/input_error.hpp"

namespace stc {
namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// The whole of `text` as a finite double, else nullopt.
std::optional<double> finiteNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> positiveCount(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9) return std::nullopt;
  return std::stoi(text);
}

std::string written(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", kSweepValueDigits, value);
  return text;
}

/// Splits "FROM:TO:COUNT" into its three parts (trimmed), or nullopt when there are not three.
std::optional<std::vector<std::string>> threeParts(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  for (std::size_t colon; (colon = text.find(':', begin)) != std::string::npos; begin = colon + 1)
    parts.push_back(trim(text.substr(begin, colon - begin)));
  parts.push_back(trim(text.substr(begin)));
  if (parts.size() != 3) return std::nullopt;
  return parts;
}

[[noreturn]] void refuse(const std::string& text, const std::string& rule) {
  throw InputError("--set-range '" + text + "': " + rule);
}

}  // namespace

SweepRange parseSweepRange(const std::string& text) {
  const auto fail = [&](const std::string& rule) { refuse(text, rule); };
  const auto equals = text.find('=');
  const std::string form = "expected KEY=FROM:TO:COUNT (e.g. contact.friction=0.05:0.5:10)";
  if (equals == std::string::npos) fail(form);
  SweepRange range;
  range.key = trim(text.substr(0, equals));
  if (range.key.empty()) fail("missing KEY; " + form);
  const auto parts = threeParts(text.substr(equals + 1));
  if (!parts) fail(form);
  const auto from = finiteNumber((*parts)[0]), to = finiteNumber((*parts)[1]);
  if (!from) fail("FROM '" + (*parts)[0] + "' is not a finite number");
  if (!to) fail("TO '" + (*parts)[1] + "' is not a finite number");
  const auto count = positiveCount((*parts)[2]);
  if (!count || *count < 1 || *count > kMaxSweepValues)
    fail("COUNT '" + (*parts)[2] + "' must be an integer from 1 to " + std::to_string(kMaxSweepValues));
  if (*count == 1 && *from != *to) fail("COUNT = 1 needs FROM = TO (one value)");
  std::set<std::string> seen;
  for (int i = 0; i < *count; ++i) {
    const double value = *count == 1 ? *from : *from + i * (*to - *from) / (*count - 1);
    const std::string value_text = written(i == *count - 1 ? *to : value);
    if (!seen.insert(value_text).second)
      fail("values repeat once written with " + std::to_string(kSweepValueDigits) + " digits ('" + value_text + "')");
    range.texts.push_back(value_text);
    range.values.push_back(*finiteNumber(value_text));
  }
  return range;
}

}  // namespace stc
