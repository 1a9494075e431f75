#include "latin/indicator.hpp"

namespace stc::latin {

double searchNormSquared(const Eigen::VectorXd& k, const Eigen::MatrixXd& v, const Eigen::MatrixXd& lambda) {
  const double v_part = (k.asDiagonal() * v.cwiseAbs2()).sum();
  const double l_part = (k.cwiseInverse().asDiagonal() * lambda.cwiseAbs2()).sum();
  return v_part + l_part;
}

double indicator(const Eigen::VectorXd& k, const InterfaceHistory& s, const InterfaceHistory& hat) {
  // One pass over the four histories (this runs every iteration; four temporaries cost 2x more).
  double diff = 0.0, sum = 0.0;
  const Eigen::Index rows = s.v.rows();
  for (Eigen::Index col = 0; col < s.v.cols(); ++col)
    for (Eigen::Index r = 0; r < rows; ++r) {
      const double v0 = s.v(r, col), v1 = hat.v(r, col), l0 = s.lambda(r, col), l1 = hat.lambda(r, col);
      diff += k[r] * (v0 - v1) * (v0 - v1) + (l0 - l1) * (l0 - l1) / k[r];
      sum += k[r] * (v0 + v1) * (v0 + v1) + (l0 + l1) * (l0 + l1) / k[r];
    }
  if (sum == 0.0) return diff == 0.0 ? 0.0 : 1.0;
  return std::sqrt(diff) / (0.5 * std::sqrt(sum));
}

}  // namespace stc::latin
