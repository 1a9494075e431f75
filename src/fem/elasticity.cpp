#include "stcontact/fem/elasticity.hpp"

#include <algorithm>
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

Eigen::Matrix<double, 3, 6> strainDisplacement(const TriMesh& mesh, int e) {
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

Eigen::SparseMatrix<double> assembleStiffness(const TriMesh& mesh, const Eigen::Matrix3d& hooke) {
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

namespace {

// σ_vm = sqrt(½((σxx − σyy)² + (σyy − σzz)² + (σzz − σxx)²) + 3 σxy²), computed on the stresses
// divided by the largest |component| so that the squares cannot overflow where σ itself does not
// (a scene with E = 1e300 has finite stresses, and its VTU output must stay finite).
double vonMises(double sxx, double syy, double sxy, double szz) {
  const double scale = std::max({std::abs(sxx), std::abs(syy), std::abs(sxy), std::abs(szz)});
  if (!(scale > 0.0) || !std::isfinite(scale)) return scale == 0.0 ? 0.0 : scale;
  const double a = sxx / scale, b = syy / scale, c = sxy / scale, d = szz / scale;
  return scale * std::sqrt(0.5 * ((a - b) * (a - b) + (b - d) * (b - d) + (d - a) * (d - a)) + 3.0 * c * c);
}

}  // namespace

Eigen::Matrix<double, 5, Eigen::Dynamic> elementStresses(const TriMesh& mesh, const MaterialSpec& material,
                                                          PlaneModel plane, const Eigen::VectorXd& u) {
  const Eigen::Matrix3d D = hookeMatrix(material, plane);
  Eigen::Matrix<double, 5, Eigen::Dynamic> out(5, mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) {
    Eigen::Matrix<double, 6, 1> ue;
    for (int a = 0; a < 3; ++a) ue.segment<2>(2 * a) = u.segment<2>(2 * mesh.triangles(a, e));
    const Eigen::Vector3d s = D * (strainDisplacement(mesh, e) * ue);
    const double szz = plane == PlaneModel::Strain ? material.poisson * (s(0) + s(1)) : 0.0;
    out.col(e) << s(0), s(1), s(2), szz, vonMises(s(0), s(1), s(2), szz);
  }
  return out;
}

}  // namespace stc
