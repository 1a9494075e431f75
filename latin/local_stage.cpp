#include "latin/local_stage.hpp"

#include <algorithm>

#include "src/core/threads.hpp"

namespace stc::latin {
namespace {

// Nodes first … last − 1: each node's march in time touches only its own two rows.
void localStageNodes(const ContactInterface& contact, const InterfaceHistory& s, InterfaceHistory& hat, int first,
                     int last) {
  const int m = s.numSteps();
  const double mu = contact.friction;
  for (int i = first; i < last; ++i) {
    const int n = 2 * i, t = 2 * i + 1;
    const double kn = contact.search_direction[n], kt = contact.search_direction[t];
    const double g0 = contact.initial_gap[i];
    double previous_vt = 0.0;
    for (int k = 0; k < m; ++k) {
      const double vn = s.v(n, k), vt = s.v(t, k), ln = s.lambda(n, k), lt = s.lambda(t, k);
      const double ln_hat = std::max(0.0, ln - kn * (g0 + vn));
      const double c = vt - lt / kt;  // v̂_t that leaves λ̂_t = 0
      if (ln_hat == 0.0) {
        hat.v(n, k) = vn - ln / kn;
        hat.v(t, k) = c;
      } else {
        const double b = mu * ln_hat / kt;
        hat.v(n, k) = -g0;
        hat.v(t, k) = std::clamp(previous_vt, c - b, c + b);
      }
      hat.lambda(n, k) = ln_hat;
      hat.lambda(t, k) = lt + kt * (hat.v(t, k) - vt);
      previous_vt = hat.v(t, k);
    }
  }
}

}  // namespace

void localStage(const ContactInterface& contact, const InterfaceHistory& s, InterfaceHistory& hat) {
  const int nc = contact.size(), m = s.numSteps();
  hat.v.resize(2 * nc, m);
  hat.lambda.resize(2 * nc, m);
  // Contiguous ranges of nodes, one per thread (the rows of neighbouring nodes share cache lines).
  parallelRanges(nc, threadCount(), [&](int first, int last) { localStageNodes(contact, s, hat, first, last); });
}

}  // namespace stc::latin
