#pragma once
// Guard for a defect of toml++ 3.3.0 (Debian 12's libtomlplusplus-dev), found by fuzzing
// (tests/fuzz/fuzz_scene.cpp): in an array, where a value must come (after '[' or ','
// and any blanks, line ends and comments), a '}' is handed to parse_value(), which assumes it is
// given no value terminator (TOML_ASSERT_ASSUME): an assertion failure with assertions on,
// __builtin_assume of a false condition (undefined behaviour) in a clang release build; GCC 12
// has no such builtin and reports a syntax error. `a = [}`, `a = [1, }]`, `a = {b = [}]}`.
// This guard finds that '}' first and reports the syntax error itself.
#include <string_view>

#include "stcontact/scene/detail/scene_errors.hpp"

namespace stc::detail {

/// Throws "FILE:LINE:COLUMN: TOML syntax error: ..." (ErrorReporter::failAt) for the first '}'
/// of `text` (ASCII) that stands where an array expects a value. A text in which brackets stop
/// matching is left to the parser, which stops there with its own error.
void refuseBraceForArrayValue(std::string_view text, const ErrorReporter& errors);

}  // namespace stc::detail
