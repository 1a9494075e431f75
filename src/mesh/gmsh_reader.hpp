#pragma once
// Reader for 2D and 3D meshes in Gmsh's MSH 4.1 ASCII format ("4.1 0 8"), the format written by
// `Mesh.MshFileVersion = 4.1;` (Gmsh reference manual, §"MSH file format", version 4.1).
//
// What is read:
//  - $MeshFormat: must be 4.1 ASCII; any other version or the binary form is an InputError.
//  - $PhysicalNames: names of physical groups; a group without a name is named by its number.
//  - $Entities: which physical groups each curve carries.
//  - $Nodes: all nodes must lie in the plane z = 0 (|z| <= 1e-12 max(1, |x|, |y|)), else
//    "not a 2D mesh". Parametric coordinates, when present, are skipped.
//  - $Elements: 3-node triangles (type 2) become TriMesh::triangles, in file order; 2-node lines
//    (type 1) on a curve that carries physical groups become edges of a BoundaryGroup for each of
//    that curve's group names; points (type 15) are ignored. Any other element type (quadrangles,
//    second-order elements, 3D elements) is an InputError naming the type.
//  Other sections ($Periodic, $NodeData, ...) are skipped. $Nodes must precede $Elements.
//
// 3D (readGmsh3d): nodes anywhere; 4-node tetrahedra (type 4) become TetMesh::tets, in file order,
// two nodes swapped where the volume is negative (Gmsh does not promise an orientation; a flat
// tetrahedron is an InputError naming its tag and line); 3-node triangles on a surface that carries
// physical groups become triangles of a SurfaceGroup for each of its group names, oriented outward
// (as the boundary face of the body they are; a triangle that is not a boundary face is an
// InputError); lines and points are skipped; only the nodes tetrahedra use are kept. A 2D read of
// a file with tetrahedra says to set dimension = 3.
//
// Nodes: only the nodes used by some triangle are kept (an unused node would add a zero row to
// the stiffness), renumbered 0..N-1 in the order of the file. A boundary edge that uses a node
// no triangle uses is an InputError.
//
// Conformity: two elements (triangles, tetrahedra) on the same side of an edge (face) they share
// repeat or overlap each other and are an InputError naming both tags; so is a boundary element that
// is not on the body's boundary (a line between two triangles, a triangle between two tetrahedra)
// or that its group already holds. Overlaps that share no edge (face) are not detected.
//
// Orientation: Gmsh writes the triangles of a plane surface with one orientation, that of the
// surface's normal. If every triangle is clockwise (a surface whose normal is -z), all are
// flipped to counter-clockwise. If only some are, nothing is flipped and the first inverted (or
// flat) triangle is an InputError naming its element tag and line: a mixed orientation means a
// broken file, which no silent repair should hide.
//
// Every error is an InputError whose message starts with the file name and, where it points at
// a line, the line number: "part.msh: line 57: expected 3 numbers (x y z) for node 12, found 2",
// "part.msh: truncated file (expected $EndNodes)". A file cut anywhere gives an InputError.
#include <filesystem>
#include <istream>
#include <string>

#include "stcontact/mesh/tet_mesh.hpp"
#include "stcontact/mesh/tri_mesh.hpp"

namespace stc {

/// Reads `file` (see the top of this header). A file that cannot be opened is an InputError
/// "cannot open mesh file 'X'" (a MissingFileError when it does not exist). The mesh is finalised
/// (group nodes filled) and validated.
TriMesh readGmsh(const std::filesystem::path& file);

/// Parses MSH 4.1 ASCII text from `in`; `source_name` prefixes every error message.
TriMesh parseGmsh(std::istream& in, const std::string& source_name);

/// The 3D reader (see the top of this header): finalised and validated.
TetMesh readGmsh3d(const std::filesystem::path& file);
TetMesh parseGmsh3d(std::istream& in, const std::string& source_name);

/// A triangulated surface in 3D (a rigid obstacle, src/contact/surface_obstacle.hpp): the 3-node
/// triangles of the file (those of its physical surfaces when Gmsh saves only those), in file order
/// and as oriented in the file, and the nodes they use, renumbered in file order. Lines and points
/// are skipped; tetrahedra are an InputError (a volume mesh is not a surface), so is a file without
/// triangles or with a degenerate one (zero area, named by element tag and line).
struct SurfaceTriangles {
  Eigen::Matrix3Xd nodes;
  Eigen::Matrix3Xi triangles;
};
SurfaceTriangles readGmshSurface(const std::filesystem::path& file);
SurfaceTriangles parseGmshSurface(std::istream& in, const std::string& source_name);

}  // namespace stc
