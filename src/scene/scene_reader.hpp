#pragma once
// Reads and validates a scene file (TOML, through toml++), applying `--set section.key=value`
// overrides first. Every key is checked: unknown key, wrong type, out-of-range value, missing
// required key all throw InputError with "FILE: key 'section.key': rule" style messages.
#include <filesystem>
#include <string>
#include <vector>

#include "src/scene/scene.hpp"

namespace stc {

/// Parses `text` as if read from `source` (used for messages and relative mesh paths).
Scene parseScene(const std::string& text, const std::filesystem::path& source,
                 const std::vector<std::string>& overrides = {});

/// Reads the file, then parseScene. A missing or unreadable file is an InputError.
Scene readScene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

}  // namespace stc
