#pragma once
// A report's CSV file read back as rows of named cells (the end-to-end tests of `compare` and
// `sweep`). Cells hold no commas in these reports, so a plain split is exact.
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace stc::test {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};

inline std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

/// Empty when the file is missing or empty.
inline CsvTable readCsv(const std::filesystem::path& file) {
  CsvTable t;
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line)) return t;
  t.header = splitCsvLine(line);
  while (std::getline(in, line)) {
    const auto cells = splitCsvLine(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < t.header.size() && i < cells.size(); ++i) row[t.header[i]] = cells[i];
    t.rows.push_back(std::move(row));
  }
  return t;
}

/// The number in a cell; empty for an empty cell.
inline std::optional<double> number(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  return std::stod(cell);
}

/// The whole of a text file.
inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace stc::test
