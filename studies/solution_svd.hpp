#pragma once
// The a posteriori analysis of docs/method.md §3 and the seed paper's §3 (Figs. 2 and 3), for
// verification only: the incremental solution's full displacement history U (n × m), rebuilt with
// the factor of K_ff the incremental solve prepared, and its SVD in the energy product by ARPACK
// (pgd/space_time_svd.hpp). What `stcontact svd` and the Python module's svd() share.
#include <Eigen/Core>

#include "stcontact/pgd/space_time_svd.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"
#include "stcontact/solver/solve_summary.hpp"

namespace stc {

/// Singular pairs computed at least: the seed's Fig. 3a shows 50.
inline constexpr int kSvdFigurePairs = 50;

/// Refuses, with an InputError, fewer than 3 instants or `modes` outside [1, m − 1].
void checkSvdSizes(int instants, int modes);

struct SolutionHistory {
  SolveResult solved;   ///< the incremental solve
  double solve_s = 0.0;
  Eigen::MatrixXd U;    ///< n × m full displacements; empty when the solve did not converge
};

/// Solves `problem` with the incremental solver (`callback`: progress, Ctrl-C) and rebuilds U from
/// its forces with the same factor of K_ff.
SolutionHistory incrementalHistory(const Problem& problem, const IterationCallback& callback = {});

/// The energy SVD of U by ARPACK: at least kSvdFigurePairs pairs and `modes`, at most m − 1.
pgd::SpaceTimeSvd arpackEnergySvd(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K, int modes);

}  // namespace stc
