#include "stcontact/fem/elasticity_3d.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace stc {

Eigen::Matrix<double, 6, 6> hookeMatrix3d(const MaterialSpec& material) {
  const double E = material.young, nu = material.poisson;
  const double c = E / ((1.0 + nu) * (1.0 - 2.0 * nu));
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(nu);
  D.topLeftCorner<3, 3>().diagonal().setConstant(1.0 - nu);
  D.bottomRightCorner<3, 3>().diagonal().setConstant(0.5 * (1.0 - 2.0 * nu));
  return c * D;
}

namespace {

// Gradients of the barycentric shape functions N_0..N_3 (one column each). With the edges
// a = x1 − x0, b = x2 − x0, c = x3 − x0 and 6V = (a × b) · c, the inverse transpose of [a b c] has
// the columns (b × c, c × a, a × b)/(6V), so ∇N_1 = b × c/(6V), ∇N_2 = c × a/(6V),
// ∇N_3 = a × b/(6V) and ∇N_0 = −(∇N_1 + ∇N_2 + ∇N_3) (Zienkiewicz & Taylor vol. 1,
// "Three-dimensional stress analysis").
Eigen::Matrix<double, 3, 4> shapeGradients(const TetMesh& mesh, int e) {
  const Eigen::Vector3d x0 = mesh.nodes.col(mesh.tets(0, e));
  const Eigen::Vector3d a = mesh.nodes.col(mesh.tets(1, e)) - x0;
  const Eigen::Vector3d b = mesh.nodes.col(mesh.tets(2, e)) - x0;
  const Eigen::Vector3d c = mesh.nodes.col(mesh.tets(3, e)) - x0;
  Eigen::Matrix<double, 3, 4> G;
  G.col(1) = b.cross(c);
  G.col(2) = c.cross(a);
  G.col(3) = a.cross(b);
  G /= a.cross(b).dot(c);
  G.col(0) = -(G.col(1) + G.col(2) + G.col(3));
  return G;
}

}  // namespace

Eigen::Matrix<double, 6, 12> strainDisplacement(const TetMesh& mesh, int e) {
  // Rows ε_xx, ε_yy, ε_zz, γ_yz = ∂u_y/∂z + ∂u_z/∂y, γ_xz = ∂u_x/∂z + ∂u_z/∂x,
  // γ_xy = ∂u_x/∂y + ∂u_y/∂x.
  const Eigen::Matrix<double, 3, 4> G = shapeGradients(mesh, e);
  Eigen::Matrix<double, 6, 12> B = Eigen::Matrix<double, 6, 12>::Zero();
  for (int a = 0; a < 4; ++a) {
    const double dx = G(0, a), dy = G(1, a), dz = G(2, a);
    const int x = 3 * a, y = 3 * a + 1, z = 3 * a + 2;
    B(0, x) = dx;
    B(1, y) = dy;
    B(2, z) = dz;
    B(3, y) = dz;
    B(3, z) = dy;
    B(4, x) = dz;
    B(4, z) = dx;
    B(5, x) = dy;
    B(5, y) = dx;
  }
  return B;
}

namespace {

// The nodes each node shares an element with (itself included), sorted: K's 3 × 3 blocks, column by
// column.
std::vector<std::vector<int>> nodeNeighbours(const TetMesh& mesh) {
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(mesh.numNodes()));
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) neighbours[static_cast<std::size_t>(mesh.tets(a, e))].push_back(mesh.tets(b, e));
  for (std::vector<int>& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

// K's compressed columns with every entry of its 3 × 3 node blocks stored (as the element matrices
// fill them) and set to zero: in column 3n + c, the block of the j-th of node n's sorted neighbours
// starts 3 j entries after the column's start.
Eigen::SparseMatrix<double> blockPattern(const TetMesh& mesh, const std::vector<std::vector<int>>& neighbours) {
  const int n = mesh.numDofs();
  Eigen::SparseMatrix<double> K(n, n);
  std::vector<int> sizes(static_cast<std::size_t>(n));
  for (int node = 0; node < mesh.numNodes(); ++node)
    for (int c = 0; c < 3; ++c) sizes[static_cast<std::size_t>(3 * node + c)] = 3 * static_cast<int>(neighbours[node].size());
  K.reserve(sizes);
  for (int node = 0; node < mesh.numNodes(); ++node)
    for (int c = 0; c < 3; ++c)
      for (int other : neighbours[static_cast<std::size_t>(node)])
        for (int r = 0; r < 3; ++r) K.insert(3 * other + r, 3 * node + c) = 0.0;
  K.makeCompressed();
  return K;
}

}  // namespace

// K = Σ_e Vol_e Bₑᵀ D Bₑ, scattered into the pattern of the node graph: each entry sums its elements'
// contributions in element order, as Eigen's setFromTriplets sums duplicates (the same bits), without
// the 144 triplets per element (460 MB at 106k dofs) it would sort.
Eigen::SparseMatrix<double> assembleStiffness(const TetMesh& mesh, const Eigen::Matrix<double, 6, 6>& hooke) {
  const std::vector<std::vector<int>> neighbours = nodeNeighbours(mesh);
  Eigen::SparseMatrix<double> K = blockPattern(mesh, neighbours);
  double* values = K.valuePtr();
  const int* starts = K.outerIndexPtr();
  for (int e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Matrix<double, 6, 12> B = strainDisplacement(mesh, e);
    const Eigen::Matrix<double, 12, 12> Ke = mesh.sixSignedVolume(e) / 6.0 * B.transpose() * hooke * B;
    for (int b = 0; b < 4; ++b) {  // column node
      const std::vector<int>& column_nodes = neighbours[static_cast<std::size_t>(mesh.tets(b, e))];
      for (int a = 0; a < 4; ++a) {  // row node: its block's place in each of the three columns
        const auto at = std::lower_bound(column_nodes.begin(), column_nodes.end(), mesh.tets(a, e));
        const int block = 3 * static_cast<int>(at - column_nodes.begin());
        for (int c = 0; c < 3; ++c) {
          double* column = values + starts[3 * mesh.tets(b, e) + c] + block;
          for (int r = 0; r < 3; ++r) column[r] += Ke(3 * a + r, 3 * b + c);
        }
      }
    }
  }
  return K;
}

Eigen::Matrix<double, 7, Eigen::Dynamic> elementStresses(const TetMesh& mesh, const MaterialSpec& material,
                                                          const Eigen::VectorXd& u) {
  const Eigen::Matrix<double, 6, 6> D = hookeMatrix3d(material);
  Eigen::Matrix<double, 7, Eigen::Dynamic> out(7, mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) {
    Eigen::Matrix<double, 12, 1> ue;
    for (int a = 0; a < 4; ++a) ue.segment<3>(3 * a) = u.segment<3>(3 * mesh.tets(a, e));
    const Eigen::Matrix<double, 6, 1> s = D * (strainDisplacement(mesh, e) * ue);
    const double deviatoric = 0.5 * ((s(0) - s(1)) * (s(0) - s(1)) + (s(1) - s(2)) * (s(1) - s(2)) +
                                     (s(2) - s(0)) * (s(2) - s(0)));
    out.col(e) << s, std::sqrt(deviatoric + 3.0 * s.tail<3>().squaredNorm());
  }
  return out;
}

}  // namespace stc
