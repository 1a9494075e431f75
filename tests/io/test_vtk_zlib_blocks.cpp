// The compressed DataArray layout of VTK's XML files (src/io/vtk_zlib_blocks.hpp): the header words
// for data shorter than a block, an exact number of blocks and a partial last block, and the blocks
// uncompressing back to the data (through tests/io/vtu_reading.hpp's reader).
#include "stcontact/io/vtk_zlib_blocks.hpp"

#include <gtest/gtest.h>

#include "io/vtu_reading.hpp"

namespace stc {
namespace {

/// `size` bytes that repeat with a long period (compressible, not trivially so).
std::string sampleBytes(std::size_t size) {
  std::string bytes(size, '\0');
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>((i * 7 + i / 251) % 256);
  return bytes;
}

struct Header {
  std::uint64_t blocks, blockSize, lastSize;
};

Header headerOf(const std::string& encoded) {
  return {iotest::wordAt(encoded, 0), iotest::wordAt(encoded, 8), iotest::wordAt(encoded, 16)};
}

TEST(VtkZlibBlocks, HeaderCountsBlocksAndTheLastPartialOne) {
  const std::size_t b = kVtkBlockSize;
  EXPECT_EQ(b, 32768u);
  const std::vector<std::tuple<std::size_t, std::uint64_t, std::uint64_t>> cases = {
      {100, 1, 100}, {b, 1, 0}, {2 * b, 2, 0}, {2 * b + 5, 3, 5}};
  for (const auto& [size, blocks, last] : cases) {
    const Header header = headerOf(vtkZlibBlocks(sampleBytes(size)));
    EXPECT_EQ(header.blocks, blocks) << size;
    EXPECT_EQ(header.blockSize, b) << size;
    EXPECT_EQ(header.lastSize, last) << size;
  }
}

TEST(VtkZlibBlocks, CompressedSizesAddUpAndTheBlocksUncompressToTheData) {
  for (std::size_t size : {std::size_t{1}, kVtkBlockSize, 3 * kVtkBlockSize + 1234}) {
    const std::string data = sampleBytes(size);
    const std::string encoded = vtkZlibBlocks(data);
    const std::uint64_t blocks = iotest::wordAt(encoded, 0);
    std::uint64_t compressed = 0;
    for (std::uint64_t i = 0; i < blocks; ++i) compressed += iotest::wordAt(encoded, 24 + 8 * i);
    EXPECT_EQ(encoded.size(), 24 + 8 * blocks + compressed) << size;
    std::uint64_t end = 0;
    EXPECT_EQ(iotest::uncompressedAt(encoded, 0, end), data) << size;
    EXPECT_EQ(end, encoded.size()) << size;
  }
}

TEST(VtkZlibBlocks, EmptyDataHasNoBlock) {
  const std::string encoded = vtkZlibBlocks("");
  EXPECT_EQ(encoded.size(), 24u);
  EXPECT_EQ(headerOf(encoded).blocks, 0u);
}

TEST(VtkZlibBlocks, TheSameDataGivesTheSameBytes) {
  const std::string data = sampleBytes(100000);
  EXPECT_EQ(vtkZlibBlocks(data), vtkZlibBlocks(data));
  EXPECT_LT(vtkZlibBlocks(data).size(), data.size() / 2);  // the sample is compressible
}

}  // namespace
}  // namespace stc
