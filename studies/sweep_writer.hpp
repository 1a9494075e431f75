#pragma once
// The files of a sweep report (docs/sweep.md describes every column):
//   sweep.csv   one row per value: warm and cold solves' work, true errors, end forces
//   summary.md  totals warm against cold and their ratio, the table per value, machine and build
#include <filesystem>
#include <string>

#include "stcontact/studies/sweep.hpp"

namespace stc {

std::string sweepCsv(const Sweep& sweep);
std::string sweepMarkdown(const Sweep& sweep);

/// Writes both files into `dir` (which must exist), each atomically.
void writeSweep(const std::filesystem::path& dir, const Sweep& sweep);

}  // namespace stc
