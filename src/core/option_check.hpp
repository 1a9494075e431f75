#pragma once
// The one check of an options struct's field, for every validate(): throws InputError
// "<owner> option <field> = <value>: <rule>", e.g. "FAS option max_skip = 0: must be >= 1".
// Integers print as integers; other numbers as std::to_string prints them.
#include <string>

#include "stcontact/core/input_error.hpp"

namespace stc {

inline void requireOption(bool ok, const char* owner, const char* field, int value, const char* rule) {
  if (!ok) throw InputError(std::string(owner) + " option " + field + " = " + std::to_string(value) + ": " + rule);
}

inline void requireOption(bool ok, const char* owner, const char* field, double value, const char* rule) {
  if (!ok) throw InputError(std::string(owner) + " option " + field + " = " + std::to_string(value) + ": " + rule);
}

}  // namespace stc
