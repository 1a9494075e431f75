#include "stcontact/fem/elasticity_3d.hpp"

#include <Eigen/Geometry>
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

Eigen::SparseMatrix<double> assembleStiffness(const TetMesh& mesh, const Eigen::Matrix<double, 6, 6>& hooke) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(144 * static_cast<std::size_t>(mesh.numElements()));
  for (int e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Matrix<double, 6, 12> B = strainDisplacement(mesh, e);
    const Eigen::Matrix<double, 12, 12> Ke = mesh.sixSignedVolume(e) / 6.0 * B.transpose() * hooke * B;
    for (int a = 0; a < 12; ++a)
      for (int b = 0; b < 12; ++b)
        triplets.emplace_back(3 * mesh.tets(a / 3, e) + a % 3, 3 * mesh.tets(b / 3, e) + b % 3, Ke(a, b));
  }
  Eigen::SparseMatrix<double> K(mesh.numDofs(), mesh.numDofs());
  K.setFromTriplets(triplets.begin(), triplets.end());
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
