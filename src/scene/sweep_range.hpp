#pragma once
// A parameter sweep's values (`stcontact sweep --set-range KEY=FROM:TO:COUNT`, docs/sweep.md):
// COUNT evenly spaced values from FROM to TO, both included (TO < FROM sweeps downwards),
//   value_i = FROM + i (TO − FROM) / (COUNT − 1),  i = 0 … COUNT − 1,
// each turned into the `--set KEY=VALUE` override that solves it. Whether KEY exists and the value is
// in its range is the scene reader's to say (readScene with the override), as for any --set.
#include <string>
#include <vector>

namespace stc {

struct SweepRange {
  std::string key;                  ///< "contact.friction"
  std::vector<std::string> texts;   ///< each value as written into its override ("0.1", "21")
  std::vector<double> values;       ///< the same, read back from the text: what is solved

  /// "KEY=TEXT" of value `i`, for readScene's overrides.
  std::string override(std::size_t i) const { return key + "=" + texts.at(i); }
};

/// Values are written with 12 significant digits, so that 0.05 + 0.05 is "0.1" and an integer
/// is written as one ("21", which an integer key such as mesh.arc_nodes accepts).
constexpr int kSweepValueDigits = 12;
/// At most this many values: each is solved twice (warm and cold), a larger COUNT is a typo.
constexpr int kMaxSweepValues = 1000;

/// Parses `KEY=FROM:TO:COUNT`. Throws InputError ("--set-range '<text>': <rule>") when the form is
/// not that, FROM or TO is not a finite number, COUNT is not an integer in [1, kMaxSweepValues],
/// COUNT = 1 with FROM ≠ TO, or two values are equal once written.
SweepRange parseSweepRange(const std::string& text);

}  // namespace stc
