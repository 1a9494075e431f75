#pragma once
// `--set KEY=VALUE` overrides (docs/interface.md "Command line"), applied to the parsed scene table
// before validation, so an overridden value is checked exactly like one written in the file.
//   KEY   = name | section.key | section[i].key (arrays of tables, 0-based) | ...[i] (array entry)
//   VALUE = a TOML value (scalar or array: 401, 0.3, "stress", [0.0, 0.1]); text that does not
//           parse as TOML is taken as a string (a bare word: `model.plane=stress`).
// A missing table on the way is created (`solver.tolerance` without [solver]); validation then
// rejects unknown keys, and ErrorReporter notes that they came from --set.
#include <toml++/toml.h>

#include <string>
#include <vector>

#include "stcontact/scene/detail/scene_errors.hpp"

namespace stc::detail {

/// Applies each override in order (a later one wins) and records its path in `errors`.
/// Throws InputError for a malformed override, a table value, or a path through a missing
/// array entry or a value that is not a table.
void applyOverrides(toml::table& scene, const std::vector<std::string>& overrides,
                    ErrorReporter& errors);

}  // namespace stc::detail
