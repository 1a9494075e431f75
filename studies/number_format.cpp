#include "stcontact/studies/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace stc {

std::string targetLabel(double target) {
  const double exponent = std::round(std::log10(target));
  char text[32];
  if (std::abs(std::pow(10.0, exponent) - target) <= 1e-12 * target)
    std::snprintf(text, sizeof text, "1e%d", static_cast<int>(exponent));
  else
    std::snprintf(text, sizeof text, "%g", target);
  return text;
}

std::string shortNumber(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string shortNumber(const std::optional<double>& value, int digits) {
  return value ? shortNumber(*value, digits) : "";
}

}  // namespace stc
