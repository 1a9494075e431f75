#include "stcontact/latin/indicator.hpp"

#include <cmath>

namespace stc::latin {

double searchNormSquared(const Eigen::VectorXd& k, const Eigen::MatrixXd& v, const Eigen::MatrixXd& lambda) {
  const double v_part = (k.asDiagonal() * v.cwiseAbs2()).sum();
  const double l_part = (k.cwiseInverse().asDiagonal() * lambda.cwiseAbs2()).sum();
  return v_part + l_part;
}

double indicator(const Eigen::VectorXd& k, const InterfaceHistory& s, const InterfaceHistory& hat, double* gap) {
  // One pass over the four histories (this runs every iteration; four temporaries cost 2x more).
  // Terms as (√k v)² and (λ/√k)²: k v² and λ²/k are of one size, λ² alone overflows first
  // (|λ| > 1e154, e.g. a scene with E = 1e300), which turned η into NaN.
  const Eigen::ArrayXd sqrt_k = k.array().sqrt(), inv_sqrt_k = sqrt_k.inverse();
  double diff = 0.0, sum = 0.0;
  const Eigen::Index rows = s.v.rows();
  for (Eigen::Index col = 0; col < s.v.cols(); ++col)
    for (Eigen::Index r = 0; r < rows; ++r) {
      const double v0 = s.v(r, col), v1 = hat.v(r, col), l0 = s.lambda(r, col), l1 = hat.lambda(r, col);
      const double dv = sqrt_k[r] * (v0 - v1), dl = (l0 - l1) * inv_sqrt_k[r];
      const double sv = sqrt_k[r] * (v0 + v1), sl = (l0 + l1) * inv_sqrt_k[r];
      diff += dv * dv + dl * dl;
      sum += sv * sv + sl * sl;
    }
  if (gap) *gap = std::sqrt(diff);
  if (sum == 0.0) return diff == 0.0 ? 0.0 : 1.0;
  return std::sqrt(diff) / (0.5 * std::sqrt(sum));
}

}  // namespace stc::latin
