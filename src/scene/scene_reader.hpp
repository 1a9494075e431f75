#pragma once
// Reads and validates a scene file (TOML, through toml++; docs/interface.md "Scene file"), applying
// `--set KEY=VALUE` overrides first. Every key is checked: unknown key, wrong type, non-finite or
// out-of-range value, missing required key all throw InputError with one-line messages such as
//   "hemicylinder.toml: key 'material.poisson' = 0.5 is out of range: must be in [-0.999999, 0.4999995] (1 + ν and 1 - 2ν at least 1e-6)"
//   "hemicylinder.toml:12:9: TOML syntax error: <toml++'s description>"
// Keys are named by their full dotted path, arrays of tables by 0-based index
// ("dirichlet[1].times"). Checks that need the mesh (boundary names, penetration) belong to the
// Problem builder.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "stcontact/scene/scene.hpp"

namespace stc {

/// Parses `text` as if read from `source` (used for messages and relative mesh paths).
/// `overrides` are `--set` texts: "contact.friction=0.3", "model.plane=stress",
/// "dirichlet[1].values=[0, -0.02]"; see src/scene/detail/scene_overrides.hpp.
Scene parseScene(const std::string& text, const std::filesystem::path& source,
                 const std::vector<std::string>& overrides = {});

/// The largest scene file read (64 MiB): a scene is a few kB of TOML, and a larger file (or a
/// device, which is not a regular file) would be read whole into memory.
inline constexpr std::uintmax_t kMaxSceneBytes = 64u << 20;

/// Reads the file, then parseScene. A missing or unreadable file, one that is not a regular file or
/// one larger than kMaxSceneBytes is an InputError.
Scene readScene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

}  // namespace stc
