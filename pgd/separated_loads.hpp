#pragma once
// The loads of a Problem as two matrices: f(t_k) = F g_k with F = [f_1 … f_q] (n_free × q, the
// separated load vectors) and G (q × m, their histories on the grid). Problem::loads stores them so.
#include <Eigen/Core>

#include "stcontact/problem/problem.hpp"

namespace stc::pgd {

struct SeparatedLoads {
  Eigen::MatrixXd F;  ///< n_free × q
  Eigen::MatrixXd G;  ///< q × m
};

SeparatedLoads separatedLoads(const Problem& problem);

}  // namespace stc::pgd
