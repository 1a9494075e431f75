#pragma once
// A report's text (markdown, CSV) split into its lines, for the report tests.
#include <sstream>
#include <string>
#include <vector>

namespace stc::test {

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace stc::test
