#include "stcontact/mesh/detail/box_grid.hpp"

#include <Eigen/Geometry>
#include <array>
#include <vector>

namespace stc::detail {
namespace {

// The 6 tetrahedra of cube (i, j, k) around its diagonal from the corner nearest the centre of the
// top face (nearest the axis x = y = 0 and the top z = 0) to the opposite corner: one per order in
// which the path steps along x, y, z (Kuhn's subdivision). Each is stored with positive volume in
// the reference box.
void splitCube(const BoxGrid& grid, int i, int j, int k, std::vector<std::array<int, 4>>& tets) {
  const int d = grid.divisions();
  const int origin[3] = {i >= d ? i : i + 1, j >= d ? j : j + 1, k + 1};
  const int step[3] = {i >= d ? 1 : -1, j >= d ? 1 : -1, -1};
  static constexpr int kOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& order : kOrders) {
    int corner[3] = {origin[0], origin[1], origin[2]};
    std::array<int, 4> tet;
    tet[0] = grid.id(corner[0], corner[1], corner[2]);
    for (int s = 0; s < 3; ++s) {
      corner[order[s]] += step[order[s]];
      tet[s + 1] = grid.id(corner[0], corner[1], corner[2]);
    }
    if (sixVolume(grid.reference(tet[0]), grid.reference(tet[1]), grid.reference(tet[2]), grid.reference(tet[3])) < 0)
      std::swap(tet[2], tet[3]);
    tets.push_back(tet);
  }
}

}  // namespace

Eigen::Matrix4Xi boxTetrahedra(const BoxGrid& grid, int hole) {
  const int d = grid.divisions();
  const auto inHole = [&](int i, int j, int k) {
    return k < hole && i >= d - hole && i < d + hole && j >= d - hole && j < d + hole;
  };
  std::vector<std::array<int, 4>> tets;
  tets.reserve(6 * 4 * static_cast<std::size_t>(d) * d * d);
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < 2 * d; ++j)
      for (int i = 0; i < 2 * d; ++i)
        if (!inHole(i, j, k)) splitCube(grid, i, j, k, tets);
  Eigen::Matrix4Xi out(4, static_cast<Eigen::Index>(tets.size()));
  for (std::size_t e = 0; e < tets.size(); ++e) out.col(e) << tets[e][0], tets[e][1], tets[e][2], tets[e][3];
  return out;
}

Eigen::Vector3d boxToBall(const Eigen::Vector3d& x) {
  const double norm2 = x.norm();
  if (norm2 == 0.0) return x;
  return x * (x.cwiseAbs().maxCoeff() / norm2);
}

double sixVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 const Eigen::Vector3d& e) {
  return (b - a).cross(c - a).dot(e - a);
}

}  // namespace stc::detail
