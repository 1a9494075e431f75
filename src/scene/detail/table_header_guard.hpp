#pragma once
// Guard for a defect of toml++ 3.3.0 (Debian 12's libtomlplusplus-dev), found by fuzzing
// (tests/fuzz/fuzz_scene.cpp): for a table header whose name starts with a character that cannot
// start a key ("[.a]", "[=", "[[[1]]]", "[#", "[" at the end of a line), the parser calls its
// parse_key() without checking the first character, which parse_key() assumes to be a key
// character. With assertions on, that aborts the program; without, the assumption is undefined
// behaviour (the shipped build happens to report a syntax error). Fixed upstream after 3.4
// (toml++ pull request 301). This guard finds such a header first and reports the syntax error
// itself, so the parser never sees one.
#include <string_view>

#include "stcontact/scene/detail/scene_errors.hpp"

namespace stc::detail {

/// Throws "FILE:LINE:COLUMN: TOML syntax error: ..." (ErrorReporter::failAt) for the first table
/// header of `text` whose name starts with a character that cannot start a key.
void refuseMalformedTableHeaders(std::string_view text, const ErrorReporter& errors);

}  // namespace stc::detail
