#pragma once
// One `fas-apriori` solve of a problem (docs/method.md §5): its separated stage
// (pgd/controlled_global_stage.hpp) set up with the run's operators, the FAS cycle with the a priori
// coarse spaces, nested in time on a long grid (nested_in_time.hpp), then the displacement of the
// contact nodes left out of the problem (when it is a contact zone's, zone_rounds.hpp) read from the
// separated displacement history. The level below the reduced interface's rounds; the whole solve
// when the interface is not reduced (solve_fas_apriori.cpp).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::fas {

/// Solves `problem` from inputs.start, with the directions started from inputs.basis_seed when
/// given; its records count from inputs.origin with the stage's set-up solves added. `far_v`
/// receives B_far u of the last iterate's displacement history (B_far: rows × n_free, e.g. the rows
/// of nodes left out), truncated in energy to what a converged estimate leaves of the tolerance (at
/// most (τ − ε_est)² E dropped, E the iterate's energy: pgd::ResponseBasis::displacementOn); the
/// result's spatial modes are left empty unless inputs.spatial_modes. The coarse spaces come from
/// `coarse_basis` (the a priori ones by default).
SolveResult solveAprioriOn(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs,
                           const Eigen::SparseMatrix<double>& B_far, Eigen::MatrixXd& far_v,
                           const SeparatedCoarseBasis& coarse_basis = {});

}  // namespace stc::fas
