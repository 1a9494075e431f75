#pragma once
// A writer of Gmsh MSH 4.1 ASCII files for the tests that need a mesh the generators do not make
// (two bodies meshed apart, test_hertz_3d.cpp): one volume entity holding every tetrahedron, one
// surface entity per named group. The reader (src/mesh/gmsh_reader.hpp) orients the elements, so the
// connectivity may come in either orientation.
#include <filesystem>
#include <fstream>
#include <string>

#include "stcontact/mesh/tet_mesh.hpp"

namespace stc::validation {

inline void writeMsh(const std::filesystem::path& file, const TetMesh& mesh) {
  std::ofstream out(file);
  out.precision(17);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" << mesh.groups.size() << "\n";
  int tag = 0;
  for (const auto& [name, group] : mesh.groups) out << "2 " << ++tag << " \"" << name << "\"\n";
  out << "$EndPhysicalNames\n$Entities\n0 0 " << mesh.groups.size() << " 1\n";
  for (int s = 1; s <= tag; ++s) out << s << " 0 0 0 0 0 0 1 " << s << " 0\n";
  out << "1 0 0 0 0 0 0 0 0\n$EndEntities\n$Nodes\n1 " << mesh.numNodes() << " 1 " << mesh.numNodes() << "\n3 1 0 "
      << mesh.numNodes() << "\n";
  for (int n = 1; n <= mesh.numNodes(); ++n) out << n << "\n";
  for (int n = 0; n < mesh.numNodes(); ++n)
    out << mesh.nodes(0, n) << " " << mesh.nodes(1, n) << " " << mesh.nodes(2, n) << "\n";
  std::size_t elements = static_cast<std::size_t>(mesh.numElements());
  for (const auto& [name, group] : mesh.groups) elements += group.triangles.size();
  out << "$EndNodes\n$Elements\n" << mesh.groups.size() + 1 << " " << elements << " 1 " << elements << "\n";
  long long element = 0;
  int surface = 0;
  for (const auto& [name, group] : mesh.groups) {
    out << "2 " << ++surface << " 2 " << group.triangles.size() << "\n";
    for (const auto& t : group.triangles) out << ++element << " " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  }
  out << "3 1 4 " << mesh.numElements() << "\n";
  for (int e = 0; e < mesh.numElements(); ++e)
    out << ++element << " " << mesh.tets(0, e) + 1 << " " << mesh.tets(1, e) + 1 << " " << mesh.tets(2, e) + 1 << " "
        << mesh.tets(3, e) + 1 << "\n";
  out << "$EndElements\n";
}

}  // namespace stc::validation
