#include "latin/local_stage.hpp"

#include <algorithm>

#include "src/core/threads.hpp"

namespace stc::latin {
namespace {

// P_b(x) on the tangent plane: x when |x| ≤ b, else b x/|x| (in 2D the clamp to [−b, b]).
Eigen::Vector2d projectOnDisc(const Eigen::Vector2d& x, double b) {
  const double norm = x.norm();
  return norm <= b ? x : Eigen::Vector2d(b / norm * x);
}

// Nodes first … last − 1 of a D-dimensional interface: each node's march in time touches only its
// own D rows (normal, then the T = D − 1 tangential ones).
template <int D>
void localStageNodes(const ContactInterface& contact, const InterfaceHistory& s, InterfaceHistory& hat, int first,
                     int last) {
  constexpr int T = D - 1;
  using Tangential = Eigen::Matrix<double, T, 1>;
  const int m = s.numSteps();
  const double mu = contact.friction;
  for (int i = first; i < last; ++i) {
    const int n = D * i, t = n + 1;
    const double kn = contact.search_direction[n], kt = contact.search_direction[t];
    const double g0 = contact.initial_gap[i];
    Tangential previous_vt = Tangential::Zero();
    for (int k = 0; k < m; ++k) {
      const double vn = s.v(n, k), ln = s.lambda(n, k);
      const Tangential vt = s.v.template block<T, 1>(t, k), lt = s.lambda.template block<T, 1>(t, k);
      const double ln_hat = std::max(0.0, ln - kn * (g0 + vn));
      const Tangential c = vt - lt / kt;  // v̂_t that leaves λ̂_t = 0
      Tangential vt_hat;
      if (ln_hat == 0.0) {
        hat.v(n, k) = vn - ln / kn;
        vt_hat = c;
      } else {
        hat.v(n, k) = -g0;
        if constexpr (T == 1) {
          const double b = mu * ln_hat / kt;
          vt_hat[0] = std::clamp(previous_vt[0], c[0] - b, c[0] + b);
        } else {
          vt_hat = c + projectOnDisc(previous_vt - c, mu * ln_hat / kt);
        }
      }
      hat.v.template block<T, 1>(t, k) = vt_hat;
      hat.lambda(n, k) = ln_hat;
      hat.lambda.template block<T, 1>(t, k) = lt + kt * (vt_hat - vt);
      previous_vt = vt_hat;
    }
  }
}

}  // namespace

void localStage(const ContactInterface& contact, const InterfaceHistory& s, InterfaceHistory& hat) {
  const int nc = contact.size(), m = s.numSteps();
  hat.v.resize(contact.rows(), m);
  hat.lambda.resize(contact.rows(), m);
  // Contiguous ranges of nodes, one per thread (the rows of neighbouring nodes share cache lines).
  parallelRanges(nc, threadCount(), [&](int first, int last) {
    if (contact.dimension == 3) localStageNodes<3>(contact, s, hat, first, last);
    else localStageNodes<2>(contact, s, hat, first, last);
  });
}

}  // namespace stc::latin
