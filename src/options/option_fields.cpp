#include "stcontact/options/option_fields.hpp"

#include <cmath>
#include <limits>

namespace stc {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void fail(const char* owner, const char* key, const std::string& value, const std::string& rule) {
  throw InputError(std::string(owner) + " option " + key + " = " + value + ": " + rule);
}

}  // namespace

bool Range::holds(double x) const {
  if (off && x == *off) return true;
  if (std::isnan(x)) return false;
  const bool above = low_strict ? x > low : x >= low;
  const bool below = high_strict ? x < high : x <= high;
  return above && below && std::isfinite(x);
}

Range atLeast(int n) { return {double(n), kInfinity, false, false, std::nullopt, "must be >= " + std::to_string(n)}; }
Range positive() { return {0.0, kInfinity, true, false, std::nullopt, "must be > 0"}; }
Range inOpenUnit() { return {0.0, 1.0, true, true, std::nullopt, "must be in (0, 1)"}; }
Range inUnitHalfOpen() { return {0.0, 1.0, true, false, std::nullopt, "must be in (0, 1]"}; }
Range inUnitClosed() { return {0.0, 1.0, false, false, std::nullopt, "must be in [0, 1]"}; }
Range offOrAtLeast(int n) {
  return {double(n), kInfinity, false, false, 0.0, "must be 0 (off) or >= " + std::to_string(n)};
}
Range offOrInOpenUnit() { return {0.0, 1.0, true, true, 0.0, "must be 0 (off) or in (0, 1)"}; }
Range anyFlag() { return {-kInfinity, kInfinity, false, false, std::nullopt, ""}; }

void FieldCheck::operator()(const char* key, int value, const Range& range, Exposure) const {
  if (!range.holds(value)) fail(owner_, key, std::to_string(value), range.rule);
}

void FieldCheck::operator()(const char* key, double value, const Range& range, Exposure) const {
  if (!range.holds(value)) fail(owner_, key, std::to_string(value), range.rule);
}

void requireOption(bool ok, const char* owner, const char* what, int value, const char* rule) {
  if (!ok) fail(owner, what, std::to_string(value), rule);
}

}  // namespace stc
