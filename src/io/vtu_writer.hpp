#pragma once
// ParaView output (docs/interface.md "Output files": solution.pvd + vtu/): a VTK XML UnstructuredGrid
// of the P1 triangle or tetrahedron mesh with nodal and element fields, and the collection (.pvd)
// that makes a series of them a time series. Format: "VTK File Formats", XML section (Kitware):
//   <VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64"
//            compressor="vtkZLibDataCompressor">
// every DataArray format="appended" offset="o": its data starts o bytes after the '_' that opens
// <AppendedData encoding="raw">, as zlib-compressed blocks behind their UInt64 header
// (vtk_zlib_blocks.hpp). Up to that '_' the document is plain XML. The types and component names of
// the arrays: vtu_arrays.hpp.
//
// The appended data holds the arrays in the reverse of their order in the XML (the cells' arrays
// first, the first point field last). VTK reads them by offset in any order; meshio's raw reader
// (Debian 12's python3-meshio) finds each array by the text of its offset while it rewrites the
// offsets of those it has read, and with the two orders the same an array read earlier can take the
// place of a later one whose offset happens to equal its new one.
//
// The mesh is written in every frame. VTK's XML formats cannot refer to a geometry kept in another
// file; VTKHDF keeps one mesh for a transient series but needs ParaView >= 5.12 (Debian 12 ships
// 5.11); XDMF and Exodus II need HDF5 or netCDF, and XDMF has no component names; EnSight Gold shares
// its geometry file but has no compression, no integer fields and no component names. So a frame is
// self-contained, the points and cells converted and compressed once by VtuGrid and copied into each
// file. On the 3D hemisphere scene (2601 nodes, 12288 tetrahedra, 201 frames) the series takes 72 MB
// in Float32 and 146 MB in Float64, against 416 MB for the ASCII Float64 files of version 0.3
// (docs/interface.md, "solution.pvd and vtu/").
#include <Eigen/Core>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "stcontact/io/vtu_arrays.hpp"
#include "stcontact/mesh/tet_mesh.hpp"
#include "stcontact/mesh/tri_mesh.hpp"
#include "stcontact/scene/output_spec.hpp"

namespace stc {

/// Writes the .vtu document: points (z = 0 for triangles), cells (VTK_TRIANGLE = 5, VTK_TETRA = 10),
/// then the fields. Everything is checked before the first byte is written (checkFields,
/// pointArray): std::invalid_argument names the field and the rule broken.
void writeVtu(std::ostream& out, const TriMesh& mesh, const std::vector<PointField>& pointFields,
              const std::vector<CellField>& cellFields, FieldPrecision precision = FieldPrecision::Float32);
void writeVtu(std::ostream& out, const TetMesh& mesh, const std::vector<PointField>& pointFields,
              const std::vector<CellField>& cellFields, FieldPrecision precision = FieldPrecision::Float32);
/// The same document as a string.
std::string vtuDocument(const TriMesh& mesh, const std::vector<PointField>& pointFields,
                        const std::vector<CellField>& cellFields, FieldPrecision precision = FieldPrecision::Float32);
std::string vtuDocument(const TetMesh& mesh, const std::vector<PointField>& pointFields,
                        const std::vector<CellField>& cellFields, FieldPrecision precision = FieldPrecision::Float32);

/// The documents of a series of frames on one mesh: the points and cells, the same in every frame,
/// are converted and compressed once, at construction; write() adds the fields (the checks and the
/// output are those of writeVtu).
class VtuGrid {
 public:
  explicit VtuGrid(const TriMesh& mesh, FieldPrecision precision = FieldPrecision::Float32);
  explicit VtuGrid(const TetMesh& mesh, FieldPrecision precision = FieldPrecision::Float32);
  void write(std::ostream& out, const std::vector<PointField>& pointFields,
             const std::vector<CellField>& cellFields) const;

 private:
  Eigen::Index points_, cells_;
  FieldPrecision precision_;
  EncodedArray pointArray_;               ///< <Points>
  std::vector<EncodedArray> cellArrays_;  ///< <Cells>: connectivity, offsets, types
};

/// One file of a ParaView collection: its time, its name relative to the .pvd, its part and, when not
/// empty, that part's name. ParaView's PVD reader makes the files of one time the blocks of a
/// multiblock dataset, each named by its `name` (a body, docs/two_bodies.md; vtkXMLCollectionReader).
struct PvdDataSet {
  double time = 0.0;
  std::string file;
  int part = 0;
  std::string name;
};

/// A ParaView collection listing `frames` in the given order. Throws std::invalid_argument for an
/// empty file name, a non-finite time or a negative part.
std::string pvdDocument(const std::vector<PvdDataSet>& frames);

}  // namespace stc
