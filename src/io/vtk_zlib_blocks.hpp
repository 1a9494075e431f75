#pragma once
// The bytes of one DataArray in a compressed VTK XML file (compressor="vtkZLibDataCompressor",
// header_type="UInt64"; "VTK File Formats", XML section, "Compressed data", Kitware): the raw values
// cut into blocks of kVtkBlockSize bytes (the last one possibly shorter), each compressed by zlib
// (RFC 1950), after the header
//   [#blocks][#u-size][#p-size][#c-size-1] … [#c-size-#blocks]      (UInt64 each, native byte order)
// #blocks: the number of blocks; #u-size: the size of a block before compression; #p-size: the size
// of the last block before compression when it is partial, 0 when every block is full; #c-size-i:
// the size of block i after compression. The compressed blocks follow, one after the other.
#include <cstddef>
#include <string>
#include <string_view>

namespace stc {

/// Uncompressed block size: that of VTK's own writer (vtkXMLWriter::BlockSize, 2^15).
inline constexpr std::size_t kVtkBlockSize = std::size_t{1} << 15;

/// The header and the compressed blocks of `data` (the array's values as raw bytes), ready to be
/// appended. zlib level 6 (its default); the same bytes in give the same bytes out.
std::string vtkZlibBlocks(std::string_view data);

}  // namespace stc
