#pragma once
// The one way the scene reader hands text to toml++ (the scene file and every --set value): the
// guards for the defects of toml++ 3.3.0 found by fuzzing run first (non_ascii_guard.hpp,
// table_header_guard.hpp, array_value_guard.hpp), so the parser never meets the inputs on which
// it reaches undefined behaviour.
#include <toml++/toml.h>

#include <optional>
#include <string_view>

#include "stcontact/scene/detail/scene_errors.hpp"

namespace stc::detail {

/// Parses TOML; what a guard refuses and a syntax error throw InputError
/// "FILE:LINE:COLUMN: TOML syntax error: ..." (ErrorReporter::failAt), one line.
toml::table parseGuarded(std::string_view text, const ErrorReporter& errors);

/// The same, with nothing thrown: empty when the text is refused or does not parse.
std::optional<toml::table> tryParseGuarded(std::string_view text);

}  // namespace stc::detail
