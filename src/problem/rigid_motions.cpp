#include "stcontact/problem/rigid_motions.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <sstream>

#include "stcontact/mesh/connected_parts.hpp"

namespace stc {
namespace {

/// The nodal values of the rigid motions, one column each: translations along x, y (, z), then the
/// rotations about z (2D), or about x, y, z (3D), about the centroid and divided by the body's size.
Eigen::MatrixXd rigidMotionBasis(const Eigen::MatrixXd& x) {
  const Eigen::Index d = x.rows(), n = x.cols();
  const Eigen::VectorXd centre = x.rowwise().mean();
  const Eigen::MatrixXd y = x.colwise() - centre;
  const double size = std::max(y.cwiseAbs().maxCoeff(), 1e-300);
  const Eigen::Index rotations = d == 3 ? 3 : 1;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(d * n, d + rotations);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index a = 0; a < d; ++a) R(d * i + a, a) = 1.0;
    const Eigen::VectorXd p = y.col(i) / size;
    if (d == 2) {  // ω e_z × p = (−p_y, p_x)
      R(2 * i, 2) = -p[1];
      R(2 * i + 1, 2) = p[0];
    } else {  // e_a × p for a = x, y, z
      const Eigen::Vector3d q(p[0], p[1], p[2]);
      for (int a = 0; a < 3; ++a) R.block(3 * i, 3 + a, 3, 1) = Eigen::Vector3d(Eigen::Vector3d::Unit(a)).cross(q);
    }
  }
  return R;
}

std::string describe(const Eigen::VectorXd& motion, Eigen::Index d) {
  static const char* kAxis[] = {"x", "y", "z"};
  const double largest = motion.cwiseAbs().maxCoeff();
  std::string text;
  for (Eigen::Index c = 0; c < motion.size(); ++c) {
    if (std::abs(motion[c]) < 0.1 * largest) continue;
    const bool translation = c < d;
    const Eigen::Index axis = translation ? c : (d == 2 ? 2 : c - d);
    text += (text.empty() ? "" : " with ") + std::string(translation ? "translation along " : "rotation about ") +
            kAxis[axis];
  }
  return text;
}

// The free rigid motions of the part with node positions x (d × n) whose dofs `prescribed` flags.
std::vector<std::string> freeMotionsOfPart(const Eigen::MatrixXd& x, const std::vector<char>& prescribed) {
  const Eigen::MatrixXd R = rigidMotionBasis(x);
  std::vector<Eigen::Index> rows;
  for (Eigen::Index dof = 0; dof < R.rows(); ++dof)
    if (prescribed[static_cast<std::size_t>(dof)]) rows.push_back(dof);
  std::vector<std::string> free;
  if (rows.empty()) {  // nothing prescribed: every motion is free
    for (Eigen::Index k = 0; k < R.cols(); ++k) free.push_back(describe(Eigen::VectorXd::Unit(R.cols(), k), x.rows()));
    return free;
  }
  const Eigen::MatrixXd Rp = R(rows, Eigen::all);
  // A held motion moves some prescribed dof by a share of its size: σ ≥ that share. A free one: σ = 0
  // to round-off.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Rp, Eigen::ComputeFullV);
  const Eigen::VectorXd sigma = svd.singularValues();
  const double floor = 1e-8 * std::sqrt(static_cast<double>(rows.size()));
  for (Eigen::Index k = 0; k < R.cols(); ++k) {
    const double s = k < sigma.size() ? sigma[k] : 0.0;
    if (s <= floor) free.push_back(describe(svd.matrixV().col(k), x.rows()));
  }
  return free;
}

}  // namespace

std::vector<std::string> freeRigidMotions(const BodyMesh& body, const std::vector<char>& prescribed) {
  const Eigen::MatrixXd x = nodePositions(body);
  const std::vector<std::vector<int>> parts = connectedParts(body);
  if (parts.size() == 1) return freeMotionsOfPart(x, prescribed);
  const Eigen::Index d = x.rows();
  std::vector<std::string> free;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    std::vector<char> flags;
    for (int node : parts[p])
      for (Eigen::Index a = 0; a < d; ++a) flags.push_back(prescribed[static_cast<std::size_t>(d * node + a)]);
    const Eigen::MatrixXd xp = x(Eigen::all, parts[p]);
    const std::vector<std::string> motions = freeMotionsOfPart(xp, flags);
    if (motions.empty()) continue;
    std::ostringstream text;
    text.precision(3);
    text << "body " << p + 1 << " of " << parts.size() << ", around (";
    const Eigen::VectorXd centre = xp.rowwise().mean();
    for (Eigen::Index a = 0; a < d; ++a) text << (a > 0 ? ", " : "") << (std::abs(centre[a]) < 1e-12 ? 0.0 : centre[a]);
    text << "):";
    for (std::size_t k = 0; k < motions.size(); ++k) text << (k > 0 ? ", " : " ") << motions[k];
    free.push_back(text.str());
  }
  return free;
}

}  // namespace stc
