#include "stcontact/io/vtk_zlib_blocks.hpp"

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace stc {
namespace {

constexpr int kZlibLevel = 6;  ///< zlib's default trade-off (Z_DEFAULT_COMPRESSION)

void appendWord(std::string& out, std::uint64_t word) {
  char bytes[sizeof word];
  std::memcpy(bytes, &word, sizeof word);
  out.append(bytes, sizeof word);
}

/// One block through zlib's compress2 (a complete zlib stream).
std::string compressedBlock(std::string_view block) {
  uLongf size = compressBound(static_cast<uLong>(block.size()));
  std::string out(size, '\0');
  const int status = compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(block.data()),
                               static_cast<uLong>(block.size()), kZlibLevel);
  if (status != Z_OK) throw std::runtime_error("zlib compress2 failed with status " + std::to_string(status));
  out.resize(size);
  return out;
}

}  // namespace

std::string vtkZlibBlocks(std::string_view data) {
  std::vector<std::string> blocks;
  for (std::size_t begin = 0; begin < data.size(); begin += kVtkBlockSize)
    blocks.push_back(compressedBlock(data.substr(begin, kVtkBlockSize)));
  std::string out;
  appendWord(out, blocks.size());
  appendWord(out, kVtkBlockSize);
  appendWord(out, data.size() % kVtkBlockSize);
  for (const std::string& block : blocks) appendWord(out, block.size());
  for (const std::string& block : blocks) out += block;
  return out;
}

}  // namespace stc
