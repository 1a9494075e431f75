#pragma once
// A reader of the .vtu documents src/io/vtu_writer.hpp writes, written from the format and not from
// the writer ("VTK File Formats", XML section, Kitware): the XML before the '_' that opens
// <AppendedData encoding="raw"> read with regular expressions; each DataArray's data found at its
// offset past that '_' as [#blocks][#u-size][#p-size][#c-size-1…] (UInt64, little-endian) and the
// zlib blocks, uncompressed by zlib's uncompress.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

namespace stc::iotest {

struct VtuArray {
  std::map<std::string, std::string> attributes;  ///< type, Name, NumberOfComponents, ComponentName0…
  std::vector<double> values;                     ///< the uncompressed values, in file order
  std::uint64_t end = 0;                          ///< offset past its last byte in the appended data
};

struct VtuFile {
  std::string xml;  ///< the document without the appended bytes: plain, well-formed XML
  std::map<std::string, std::vector<VtuArray>> sections;  ///< PointData, CellData, Points, Cells

  /// The array called `name` in `section`; a test failure and an empty array when there is none.
  const VtuArray& array(const std::string& section, const std::string& name) const {
    static const VtuArray none;
    if (sections.count(section))
      for (const VtuArray& a : sections.at(section))
        if (a.attributes.count("Name") && a.attributes.at("Name") == name) return a;
    ADD_FAILURE() << "no DataArray '" << name << "' in <" << section << ">";
    return none;
  }
};

inline std::uint64_t wordAt(const std::string& data, std::size_t at) {
  if (at + 8 > data.size()) throw std::runtime_error("appended data ends inside a block header");
  unsigned char bytes[8];
  std::memcpy(bytes, data.data() + at, 8);
  std::uint64_t word = 0;
  for (int i = 7; i >= 0; --i) word = word << 8 | bytes[i];
  return word;
}

/// The uncompressed bytes of the array at `offset`; `end` set past its compressed blocks.
inline std::string uncompressedAt(const std::string& data, std::uint64_t offset, std::uint64_t& end) {
  const std::uint64_t blocks = wordAt(data, offset), blockSize = wordAt(data, offset + 8),
                      lastSize = wordAt(data, offset + 16);
  std::uint64_t at = offset + 24 + 8 * blocks;
  std::string bytes;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressed = wordAt(data, offset + 24 + 8 * b);
    const uLongf expected = b + 1 == blocks && lastSize != 0 ? lastSize : blockSize;
    uLongf size = expected;
    std::string block(size, '\0');
    if (at + compressed > data.size() ||
        uncompress(reinterpret_cast<Bytef*>(block.data()), &size, reinterpret_cast<const Bytef*>(data.data() + at),
                   compressed) != Z_OK ||
        size != expected)
      throw std::runtime_error("block " + std::to_string(b) + " does not uncompress to its size");
    bytes += block;
    at += compressed;
  }
  end = at;
  return bytes;
}

template <typename T>
std::vector<double> valuesAs(const std::string& bytes) {
  std::vector<double> values(bytes.size() / sizeof(T));
  for (std::size_t k = 0; k < values.size(); ++k) {
    T value;
    std::memcpy(&value, bytes.data() + k * sizeof(T), sizeof(T));
    values[k] = static_cast<double>(value);
  }
  return values;
}

inline std::vector<double> decode(const std::string& type, const std::string& bytes) {
  if (type == "Float32") return valuesAs<float>(bytes);
  if (type == "Float64") return valuesAs<double>(bytes);
  if (type == "Int8") return valuesAs<std::int8_t>(bytes);
  if (type == "UInt8") return valuesAs<std::uint8_t>(bytes);
  if (type == "Int32") return valuesAs<std::int32_t>(bytes);
  if (type == "Int64") return valuesAs<std::int64_t>(bytes);
  throw std::runtime_error("unexpected DataArray type " + type);
}

inline VtuFile readVtu(const std::string& document) {
  const std::string opening = "<AppendedData encoding=\"raw\">", closing = "\n  </AppendedData>";
  const std::size_t open = document.find(opening), underscore = document.find('_', open);
  const std::size_t close = document.rfind(closing);
  if (open == std::string::npos || underscore == std::string::npos || close == std::string::npos || close < underscore)
    throw std::runtime_error("no <AppendedData encoding=\"raw\"> … </AppendedData>");
  const std::string header = document.substr(0, underscore), data = document.substr(underscore + 1, close - underscore - 1);
  VtuFile file;
  file.xml = document.substr(0, open + opening.size()) + document.substr(close);
  const std::regex arrayTag(R"(<DataArray([^>]*)/>)"), attribute(R"re((\w+)="([^"]*)")re");
  for (const std::string section : {"PointData", "CellData", "Points", "Cells"}) {
    const std::size_t begin = header.find("<" + section), end = header.find("</" + section + ">");
    if (begin == std::string::npos || end == std::string::npos) continue;
    const std::string body = header.substr(begin, end - begin);
    std::vector<VtuArray>& arrays = file.sections[section];
    for (std::sregex_iterator it(body.begin(), body.end(), arrayTag), last; it != last; ++it) {
      VtuArray array;
      const std::string tag = (*it)[1];
      for (std::sregex_iterator a(tag.begin(), tag.end(), attribute); a != last; ++a) array.attributes[(*a)[1]] = (*a)[2];
      const std::string bytes = uncompressedAt(data, std::stoull(array.attributes.at("offset")), array.end);
      array.values = decode(array.attributes.at("type"), bytes);
      arrays.push_back(array);
    }
  }
  return file;
}

/// Bytes of the appended data (between the '_' and "\n  </AppendedData>").
inline std::size_t appendedSize(const std::string& document) {
  const std::size_t underscore = document.find('_', document.find("<AppendedData"));
  return document.rfind("\n  </AppendedData>") - underscore - 1;
}

}  // namespace stc::iotest
