// Sizes: divisions = 8 gives (2·8 + 1)²(8 + 1) = 2601 nodes, 7803 dofs, 6·16·16·8 = 12288 tetrahedra
// (tests/mesh/test_half_ball.cpp checks them).
#include "src/mesh/half_ball.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "src/core/input_error.hpp"

namespace stc {
namespace {

// The structured grid of the box: node (i, j, k), 0 <= i, j <= 2d, 0 <= k <= d, at
// x = (i − d)/d, y = (j − d)/d, z = k/d − 1.
class BoxGrid {
 public:
  explicit BoxGrid(int divisions) : d_(divisions), side_(2 * divisions + 1) {}

  int id(int i, int j, int k) const { return i + side_ * (j + side_ * k); }
  int layer(int id) const { return id / (side_ * side_); }  // k
  int numNodes() const { return side_ * side_ * (d_ + 1); }
  int divisions() const { return d_; }

  Eigen::Vector3d reference(int id) const {
    const int i = id % side_, j = (id / side_) % side_, k = layer(id);
    return {double(i - d_) / d_, double(j - d_) / d_, double(k) / d_ - 1.0};
  }

  // ‖x − P‖_∞ with P = (0, 0, −1), from the integer indices so that the faces stay exact.
  double poleDistance(int id) const {
    const int i = id % side_, j = (id / side_) % side_, k = layer(id);
    return double(std::max({std::abs(i - d_), std::abs(j - d_), k})) / d_;
  }

 private:
  int d_, side_;
};

Eigen::Vector3d gradeTowardPole(const Eigen::Vector3d& x, double s, double exponent) {
  const Eigen::Vector3d pole(0.0, 0.0, -1.0);
  if (s == 0.0) return pole;
  return pole + std::pow(s, exponent - 1.0) * (x - pole);
}

Eigen::Vector3d boxToBall(const Eigen::Vector3d& x) {
  const double norm2 = x.norm();
  if (norm2 == 0.0) return x;
  return x * (x.cwiseAbs().maxCoeff() / norm2);
}

Eigen::Matrix3Xd placeNodes(const BoxGrid& grid, const HalfBallOptions& options) {
  Eigen::Matrix3Xd nodes(3, grid.numNodes());
  for (int n = 0; n < grid.numNodes(); ++n) {
    const Eigen::Vector3d graded = gradeTowardPole(grid.reference(n), grid.poleDistance(n), options.grading);
    nodes.col(n) = options.radius * boxToBall(graded);
  }
  return nodes;
}

double sixVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 const Eigen::Vector3d& e) {
  return (b - a).cross(c - a).dot(e - a);
}

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

Eigen::Matrix4Xi buildTets(const BoxGrid& grid) {
  const int d = grid.divisions();
  std::vector<std::array<int, 4>> tets;
  tets.reserve(6 * 4 * static_cast<std::size_t>(d) * d * d);
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < 2 * d; ++j)
      for (int i = 0; i < 2 * d; ++i) splitCube(grid, i, j, k, tets);
  Eigen::Matrix4Xi out(4, static_cast<Eigen::Index>(tets.size()));
  for (std::size_t e = 0; e < tets.size(); ++e) out.col(e) << tets[e][0], tets[e][1], tets[e][2], tets[e][3];
  return out;
}

// Boundary triangles with all three nodes on the layer k = d are the flat top; the others are curved.
void addGroups(const BoxGrid& grid, TetMesh& mesh) {
  const int d = grid.divisions();
  for (const auto& triangle : boundaryTriangles(mesh)) {
    const bool top = std::all_of(triangle.begin(), triangle.end(), [&](int n) { return grid.layer(n) == d; });
    mesh.groups[top ? "top" : "contact"].triangles.push_back(triangle);
  }
  mesh.finalizeGroups();
}

}  // namespace

void HalfBallOptions::validate() const {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InputError("half_ball: radius = " + std::to_string(radius) + " must be > 0");
  if (divisions < 2) throw InputError("half_ball: divisions = " + std::to_string(divisions) + " must be >= 2");
  if (!(grading >= 1.0) || !(grading <= 2.0))
    throw InputError("half_ball: grading = " + std::to_string(grading) + " must be in [1, 2]");
}

TetMesh makeHalfBall(const HalfBallOptions& options) {
  options.validate();
  const BoxGrid grid(options.divisions);
  TetMesh mesh;
  mesh.nodes = placeNodes(grid, options);
  mesh.tets = buildTets(grid);
  addGroups(grid, mesh);
  mesh.validate();
  return mesh;
}

}  // namespace stc
