#pragma once
// Shared pieces of the validation tests (tests/validation/): the seed scene solved once by both
// solvers, contact resultants, the contact states of an instant, and a robust estimate of the
// half-width of a semi-elliptical traction from nodal forces.
#include <memory>
#include <vector>

#include "stcontact/contact/contact_state.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::validation {

/// LATIN indicator tolerance used on the seed scene. Measured on the seed (arc_nodes 101, steps 201,
/// κ = 3; tests/validation/test_latin_vs_incremental.cpp prints the numbers): at indicator η the
/// equilibrated iterate differs from the incremental reference by ≈ 6η in max |λ| (relative),
/// ≈ 0.2η in the total reactions, ≈ 0.13η in the displacements and ≈ 0.5η in energy, for every η from
/// 1e-6 down to 1e-10. 1e-9 therefore puts all of them ≥ 150 times under the 1e-6 of the validation
/// for 220 iterations (≈ 1 s in Release).
inline constexpr double kSeedLatinTolerance = 1e-9;
/// κ of the search direction for LATIN on the seed: the measured optimum (docs/method.md §2).
inline constexpr double kSeedSearchScale = 3.0;

/// The seed scene (docs/method.md §6, arc_nodes 101, steps 201) with κ = 3, solved by the incremental
/// solver and by LATIN at kSeedLatinTolerance, and K_ff factorised. Solved once per process.
struct SeedSolutions {
  Problem problem;
  SolveResult incremental;
  SolveResult latin;
  std::unique_ptr<CholmodFactor> stiffness_free;
};
const SeedSolutions& seedSolutions();

/// Σ_i λ_n,i and Σ_i λ_t,i at instant k (the total reactions of the foundation on the body).
struct Resultant {
  double normal = 0.0;
  double tangential = 0.0;
};
Resultant resultant(const Eigen::MatrixXd& lambda, int k);

/// x coordinate (reference configuration) of every potential contact node.
std::vector<double> contactX(const Problem& problem);

/// Slip increment Δv_t = v_t(t_k) − v_t(t_{k−1}) of node i (v_t(t_{−1}) = 0).
double slipIncrement(const InterfaceHistory& h, int i, int k);

/// Open / stick / slip of every node at instant k, with the history's largest |λ| and |v| as
/// scales (as the writers classify them).
std::vector<ContactState> contactStates(const Problem& problem, const InterfaceHistory& h, int k);

/// Centre and half-width of a traction known through nodal forces w_i ≥ 0 at nodes x_i with uniform
/// spacing h, assuming the semicircle law w(x) ∝ √(1 − (x − e)²/a²) (Hertz pressure; Cattaneo's
/// stick-zone traction deficit). Its second central moment is a²/4, and P1 nodal forces weigh x² by
/// its piecewise-linear interpolant, which exceeds x² by h²/6 on average over an element, so
///   a² = 4 (Σ w x² / Σ w − e² − h²/6),  e = Σ w x / Σ w.
/// Unlike the last loaded node it is not quantised by h; unlike a pointwise fit it averages out the
/// node-to-node ripple of P1 contact forces (±2–4 % on the graded half-disc mesh).
struct SemicircleFit {
  double centre = 0.0;
  double half_width = 0.0;
  double total = 0.0;
};
SemicircleFit semicircleFromMoments(const std::vector<double>& x, const std::vector<double>& w, double h);

/// Nodal normal forces λ_n,i at instant k.
std::vector<double> normalForces(const Eigen::MatrixXd& lambda, int k);

}  // namespace stc::validation
