#include "src/fem/elasticity.hpp"

#include <cmath>
#include <vector>

namespace stc {

Eigen::Matrix3d hookeMatrix(const MaterialSpec& material, PlaneModel plane) {
  const double E = material.young, nu = material.poisson;
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  if (plane == PlaneModel::Strain) {
    const double c = E / ((1.0 + nu) * (1.0 - 2.0 * nu));
    D << 1.0 - nu, nu, 0.0, nu, 1.0 - nu, 0.0, 0.0, 0.0, 0.5 * (1.0 - 2.0 * nu);
    D *= c;
  } else {
    const double c = E / (1.0 - nu * nu);
    D << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
    D *= c;
  }
  return D;
}

Eigen::Matrix<double, 3, 6> strainDisplacement(const Mesh& mesh, int e) {
  // Shape function gradients of the linear triangle: ∂N_a/∂x = (y_b − y_c)/(2A), ∂N_a/∂y = (x_c − x_b)/(2A).
  const double area2 = mesh.twiceSignedArea(e);
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector2d pb = mesh.nodes.col(mesh.triangles((a + 1) % 3, e));
    const Eigen::Vector2d pc = mesh.nodes.col(mesh.triangles((a + 2) % 3, e));
    const double dx = (pb.y() - pc.y()) / area2, dy = (pc.x() - pb.x()) / area2;
    B(0, 2 * a) = dx;
    B(1, 2 * a + 1) = dy;
    B(2, 2 * a) = dy;
    B(2, 2 * a + 1) = dx;
  }
  return B;
}

Eigen::SparseMatrix<double> assembleStiffness(const Mesh& mesh, const Eigen::Matrix3d& hooke) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(36 * static_cast<std::size_t>(mesh.numElements()));
  for (int e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Matrix<double, 3, 6> B = strainDisplacement(mesh, e);
    const Eigen::Matrix<double, 6, 6> Ke = 0.5 * mesh.twiceSignedArea(e) * B.transpose() * hooke * B;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        triplets.emplace_back(2 * mesh.triangles(a / 2, e) + a % 2, 2 * mesh.triangles(b / 2, e) + b % 2, Ke(a, b));
  }
  Eigen::SparseMatrix<double> K(mesh.numDofs(), mesh.numDofs());
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

Eigen::Matrix<double, 5, Eigen::Dynamic> elementStresses(const Mesh& mesh, const MaterialSpec& material,
                                                          PlaneModel plane, const Eigen::VectorXd& u) {
  const Eigen::Matrix3d D = hookeMatrix(material, plane);
  Eigen::Matrix<double, 5, Eigen::Dynamic> out(5, mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) {
    Eigen::Matrix<double, 6, 1> ue;
    for (int a = 0; a < 3; ++a) ue.segment<2>(2 * a) = u.segment<2>(2 * mesh.triangles(a, e));
    const Eigen::Vector3d s = D * (strainDisplacement(mesh, e) * ue);
    const double szz = plane == PlaneModel::Strain ? material.poisson * (s(0) + s(1)) : 0.0;
    const double vm = std::sqrt(0.5 * ((s(0) - s(1)) * (s(0) - s(1)) + (s(1) - szz) * (s(1) - szz) +
                                       (szz - s(0)) * (szz - s(0))) + 3.0 * s(2) * s(2));
    out.col(e) << s(0), s(1), s(2), szz, vm;
  }
  return out;
}

}  // namespace stc
