#pragma once
// Guard for a defect of toml++ 3.3.0 (Debian 12's libtomlplusplus-dev), found by fuzzing
// (tests/fuzz/fuzz_scene.cpp): its test for non-ASCII horizontal whitespace reaches
// TOML_UNREACHABLE, undefined behaviour, for many code points (U+00A1..U+0499 among them: '°',
// 'µ', Greek, Cyrillic) wherever the parser asks "is this whitespace?" of a non-ASCII character:
// outside strings and comments, after a backslash in a string, and at the start of a line
// continued by a backslash in a multi-line string (toml++ issues 190 and 295, fixed upstream
// after 3.4). TOML 1.0 allows non-ASCII text only inside strings and comments, so this guard
// reports every such character elsewhere as the syntax error it is, and refuses the one valid
// form toml++ cannot read (the continued line), before the parser sees any of them.
// The scan knows TOML's strings and comments, not toml++'s view of a malformed line (in
// `a = 5.\"é` it sees a string, toml++ a number whose end it looks for), so the reader also parses
// asciiStandIn(text) first: a text that fails there never reaches the parser with its non-ASCII
// characters (a fuzzing finding, tests/fuzz/seeds/scene/number_then_quote.toml).
#include <string>
#include <string_view>

#include "stcontact/scene/detail/scene_errors.hpp"

namespace stc::detail {

/// Throws "FILE:LINE:COLUMN: TOML syntax error: ..." (ErrorReporter::failAt) for the first
/// non-ASCII byte of `text` that is outside a string and a comment, follows a backslash in a
/// string, or starts a line continued by a backslash in a multi-line string.
void refuseMisplacedNonAscii(std::string_view text, const ErrorReporter& errors);

/// `text` with every byte of a non-ASCII character replaced by '~' (a leading byte order mark
/// kept): the same lines and byte offsets, ASCII after the mark. '~' is TOML only where non-ASCII text is (in strings and comments), so the
/// stand-in parses exactly when the text does, once refuseMisplacedNonAscii has passed.
std::string asciiStandIn(std::string_view text);

}  // namespace stc::detail
