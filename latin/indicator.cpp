#include "latin/indicator.hpp"

namespace stc::latin {

double searchNormSquared(const Eigen::VectorXd& k, const Eigen::MatrixXd& v, const Eigen::MatrixXd& lambda) {
  const double v_part = (k.asDiagonal() * v.cwiseAbs2()).sum();
  const double l_part = (k.cwiseInverse().asDiagonal() * lambda.cwiseAbs2()).sum();
  return v_part + l_part;
}

double indicator(const Eigen::VectorXd& k, const InterfaceHistory& s, const InterfaceHistory& hat) {
  const double diff = searchNormSquared(k, s.v - hat.v, s.lambda - hat.lambda);
  const double sum = searchNormSquared(k, s.v + hat.v, s.lambda + hat.lambda);
  if (sum == 0.0) return diff == 0.0 ? 0.0 : 1.0;
  return std::sqrt(diff) / (0.5 * std::sqrt(sum));
}

}  // namespace stc::latin
