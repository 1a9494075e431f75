#pragma once
// ParaView output (docs/interface.md: solution.pvd + vtu/): a VTK XML UnstructuredGrid of the P1
// triangle or tetrahedron mesh with nodal and element fields, and the collection (.pvd) that makes a series of
// them a time series. Format: "VTK File Formats", XML section (Kitware, VTK User's Guide); ASCII
// data arrays, so the files can be read and diffed as text.
#include <Eigen/Core>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "stcontact/mesh/tet_mesh.hpp"
#include "stcontact/mesh/tri_mesh.hpp"

namespace stc {

/// Nodal values: one column per node, 1 to 3 rows (components). A two-component vector is
/// written with z = 0, so that ParaView's Warp By Vector and Glyph filters accept it.
struct PointField {
  std::string name;
  Eigen::MatrixXd values;
};

/// Element values: one column per element, one row per component (at least one), written as
/// given (e.g. a stress as the three components xx, yy, xy, or a contact state code).
struct CellField {
  std::string name;
  Eigen::MatrixXd values;
};

/// Writes the .vtu document: points (z = 0), triangles (VTK_TRIANGLE = 5), then the fields.
/// Floating-point values carry 10 significant digits (see vtu_writer.cpp). Everything is checked
/// before the first byte is written: throws std::invalid_argument naming the field if a name is
/// empty or repeated, a size does not match the mesh, or a value is NaN or infinite (VTK's
/// ASCII reader cannot read those, and stops reading the array there).
void writeVtu(std::ostream& out, const TriMesh& mesh, const std::vector<PointField>& pointFields,
              const std::vector<CellField>& cellFields);
/// The same document as a string.
std::string vtuDocument(const TriMesh& mesh, const std::vector<PointField>& pointFields,
                        const std::vector<CellField>& cellFields);

/// The same for tetrahedra (VTK_TETRA = 10), points with their z.
void writeVtu(std::ostream& out, const TetMesh& mesh, const std::vector<PointField>& pointFields,
              const std::vector<CellField>& cellFields);
std::string vtuDocument(const TetMesh& mesh, const std::vector<PointField>& pointFields,
                        const std::vector<CellField>& cellFields);

/// The document of a series of frames on one mesh: the points and cells, the same in every frame,
/// are formatted once, at construction; write() adds the fields (the checks and the output are those
/// of writeVtu).
class VtuGrid {
 public:
  explicit VtuGrid(const TriMesh& mesh);
  explicit VtuGrid(const TetMesh& mesh);
  void write(std::ostream& out, const std::vector<PointField>& pointFields,
             const std::vector<CellField>& cellFields) const;

 private:
  Eigen::Index points_, cells_;
  std::string geometry_;  ///< <Points> … </Cells>
};

/// A ParaView collection listing `frames` (time, file name relative to the .pvd) in the given
/// order. Throws std::invalid_argument for an empty file name or a non-finite time.
std::string pvdDocument(const std::vector<std::pair<double, std::string>>& frames);

}  // namespace stc
