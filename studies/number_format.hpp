#pragma once
// Number formats shared by the report writers.
#include <optional>
#include <string>

namespace stc {

/// "1e-4" for an exact power of ten, else the shortest %g form.
std::string targetLabel(double target);
/// %.<digits>g; empty for an absent value.
std::string shortNumber(double value, int digits = 4);
std::string shortNumber(const std::optional<double>& value, int digits = 4);

}  // namespace stc
