#pragma once
// Test fixture shared by the tetrahedron mesh and VTU tests.
#include "stcontact/mesh/tet_mesh.hpp"

namespace stc::test {

// The unit corner tetrahedron (0, e_x, e_y, e_z) and, sharing its face x = 0, its mirror image in x.
inline TetMesh twoTets() {
  TetMesh mesh;
  mesh.nodes.resize(3, 5);
  mesh.nodes << 0, 1, 0, 0, -1,  //
      0, 0, 1, 0, 0,             //
      0, 0, 0, 1, 0;
  mesh.tets.resize(4, 2);
  mesh.tets << 0, 0,  //
      1, 2,           //
      2, 4,           //
      3, 3;
  return mesh;
}

}  // namespace stc::test
