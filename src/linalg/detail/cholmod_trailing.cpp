#include "stcontact/linalg/detail/cholmod_trailing.hpp"

#include <stdexcept>

namespace stc::linalg {

std::vector<int> orderingWithTrailing(const cholmod_factor& analysed, const std::vector<int>& trailing) {
  const int n = static_cast<int>(analysed.n);
  std::vector<char> last(static_cast<std::size_t>(n), 0);
  for (int j : trailing) {
    if (j < 0 || j >= n || last[static_cast<std::size_t>(j)])
      throw std::invalid_argument("orderingWithTrailing: trailing dofs must be distinct and in [0, n)");
    last[static_cast<std::size_t>(j)] = 1;
  }
  const auto* perm = static_cast<const int*>(analysed.Perm);
  std::vector<int> order;
  order.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
    if (!last[static_cast<std::size_t>(perm[k])]) order.push_back(perm[k]);
  order.insert(order.end(), trailing.begin(), trailing.end());
  return order;
}

namespace {

// Supernode s holds columns super[s] … super[s+1] − 1; its row indices are s[pi[s] … pi[s+1]),
// its values a column-major nsrow × nscol block at x[px[s]] (CHOLMOD user guide, "cholmod_factor").
void readSupernodal(const cholmod_factor& L, int first, Eigen::MatrixXd& block) {
  const auto* super = static_cast<const int*>(L.super);
  const auto* pi = static_cast<const int*>(L.pi);
  const auto* px = static_cast<const int*>(L.px);
  const auto* rows = static_cast<const int*>(L.s);
  const auto* x = static_cast<const double*>(L.x);
  for (std::size_t s = 0; s < L.nsuper; ++s) {
    const int begin = super[s], end = super[s + 1], nsrow = pi[s + 1] - pi[s];
    for (int col = std::max(begin, first); col < end; ++col)
      for (int r = 0; r < nsrow; ++r)
        if (const int row = rows[pi[s] + r]; row >= col)
          block(row - first, col - first) = x[px[s] + static_cast<std::ptrdiff_t>(col - begin) * nsrow + r];
  }
}

// Column j of a simplicial factor: rows i[p[j] … p[j] + nz[j]), values x at the same places.
void readSimplicial(const cholmod_factor& L, int first, Eigen::MatrixXd& block) {
  const auto* p = static_cast<const int*>(L.p);
  const auto* nz = static_cast<const int*>(L.nz);
  const auto* rows = static_cast<const int*>(L.i);
  const auto* x = static_cast<const double*>(L.x);
  for (int col = first; col < static_cast<int>(L.n); ++col)
    for (int k = p[col]; k < p[col] + nz[col]; ++k) block(rows[k] - first, col - first) = x[k];
}

}  // namespace

Eigen::MatrixXd trailingBlock(const cholmod_factor& L, int count) {
  if (!L.is_ll || L.xtype != CHOLMOD_REAL || L.itype != CHOLMOD_INT)
    throw std::invalid_argument("trailingBlock: a real LL' factor with int indices is needed");
  const int first = static_cast<int>(L.n) - count;
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(count, count);
  if (L.is_super)
    readSupernodal(L, first, block);
  else
    readSimplicial(L, first, block);
  return block;
}

}  // namespace stc::linalg
