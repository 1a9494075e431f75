// PGD building blocks (docs/method.md §5): energy-orthonormal modes, the update (time functions of the
// Galerkin solution), greedy rank-one enrichment by alternating fixed point.
#include <gtest/gtest.h>

#include "latin/global_stage.hpp"
#include "pgd/basis_verification.hpp"
#include "pgd/energy_modes.hpp"
#include "pgd/rank_one_enrichment.hpp"
#include "pgd/separated_loads.hpp"
#include "solver/seed_scene.hpp"

namespace {

struct Fixture {
  stc::Problem problem = stc::buildProblem(stc::test::seedScene(31, 41));
  stc::latin::GlobalStage global{problem};
  const Eigen::SparseMatrix<double>& A() const { return global.matrix(); }
  double energyNorm(const Eigen::MatrixXd& U) const { return std::sqrt(U.cwiseProduct(A() * U).sum()); }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

}  // namespace

TEST(EnergyModes, StayOrthonormalAndRejectSpannedVectors) {
  const auto& f = fixture();
  stc::pgd::EnergyModes modes(f.A(), f.problem.contact.B, Eigen::MatrixXd(f.problem.numFreeDofs(), 0));
  const Eigen::MatrixXd V = Eigen::MatrixXd::Random(f.problem.numFreeDofs(), 6);
  for (int j = 0; j < 6; ++j) EXPECT_TRUE(modes.add(V.col(j)));
  EXPECT_LE(modes.orthonormalityDefect(), 1e-12);
  EXPECT_FALSE(modes.add(V.col(0) - 2.0 * V.col(3)));  // in the span: nothing appended
  EXPECT_EQ(modes.rank(), 6);
  EXPECT_LE((modes.interface() - f.problem.contact.B * modes.modes()).norm(), 1e-12 * modes.interface().norm());
}

TEST(RankOneEnrichment, ReproducesAKnownSeparatedFieldInAsManyModesAsItsRank) {
  // U = Σ_{j<3} a_j b_jᵀ, a known field (so A⁻¹ r_k = u_k): the space problem is U ψᵀ, the time
  // problem (AΥ)ᵀ U. Converged sweeps find its three energy-SVD pairs one by one; after the third,
  // what is left is round-off and the fourth candidate is negligible.
  const auto& f = fixture();
  const int n = f.problem.numFreeDofs(), m = f.problem.numSteps();
  const Eigen::MatrixXd U = Eigen::MatrixXd::Random(n, 3) * Eigen::MatrixXd::Random(3, m);
  stc::pgd::EnergyModes modes(f.A(), f.problem.contact.B, Eigen::MatrixXd(n, 0));
  const stc::pgd::SpaceProblem space = [&](const Eigen::RowVectorXd& psi) { return Eigen::VectorXd(U * psi.transpose()); };
  const stc::pgd::TimeProblem time = [&](const Eigen::VectorXd& y) {
    return Eigen::RowVectorXd((f.A() * y).transpose() * U);
  };
  stc::pgd::EnrichmentOptions options;
  options.max_sweeps = 200;
  options.sweep_tolerance = 1e-13;
  double previous = f.energyNorm(U);
  for (int j = 0; j < 3; ++j) {
    const auto pair = stc::pgd::enrichRankOne(modes, space, time, Eigen::RowVectorXd::Ones(m), options);
    ASSERT_EQ(pair.space.size(), n);
    EXPECT_LE(pair.time.norm(), previous * (1 + 1e-12));  // greedy: decreasing energies
    previous = pair.time.norm();
    ASSERT_TRUE(modes.add(pair.space));
  }
  const Eigen::MatrixXd projected = modes.modes() * (modes.modes().transpose() * (f.A() * U));
  EXPECT_LE(f.energyNorm(U - projected), 1e-9 * f.energyNorm(U));
  const auto fourth = stc::pgd::enrichRankOne(modes, space, time, Eigen::RowVectorXd::Ones(m), options);
  EXPECT_LE(fourth.time.norm(), 1e-9 * f.energyNorm(U));
}

TEST(RankOneEnrichment, UpdateIsExactWhenTheModesSpanTheSolutions) {
  // Right-hand sides r_k = F g_k + Bᵀ w_k with W of rank 2: the solutions A⁻¹ r_k live in
  // span{A⁻¹ F, A⁻¹ Bᵀ w_1, A⁻¹ Bᵀ w_2}; with those as modes the update Ψ = ΥᵀF G + (BΥ)ᵀW
  // reproduces every A⁻¹ r_k (Galerkin on a space containing the solution).
  const auto& f = fixture();
  const auto loads = stc::pgd::separatedLoads(f.problem);
  const Eigen::MatrixXd& B = f.problem.contact.B;
  const Eigen::MatrixXd w = Eigen::MatrixXd::Random(B.rows(), 2);
  const Eigen::MatrixXd W = w * Eigen::MatrixXd::Random(2, f.problem.numSteps());
  stc::pgd::EnergyModes modes(f.A(), f.problem.contact.B, loads.F);
  for (int i = 0; i < loads.F.cols(); ++i) modes.add(f.global.factor().solve(Eigen::VectorXd(loads.F.col(i))));
  for (int j = 0; j < 2; ++j) modes.add(f.global.factor().solve(Eigen::VectorXd(B.transpose() * w.col(j))));
  const Eigen::MatrixXd exact = f.global.factor().solve(Eigen::MatrixXd(loads.F * loads.G + B.transpose() * W));
  const Eigen::MatrixXd updated = modes.modes() * stc::pgd::updateTimeFunctions(modes, loads.G, W);
  EXPECT_LE(f.energyNorm(updated - exact), 1e-10 * f.energyNorm(exact));
}

TEST(BasisVerification, AnglesAndProjectionErrorsOfKnownSubspaces) {
  const auto& f = fixture();
  const int n = f.problem.numFreeDofs();
  const Eigen::MatrixXd X = Eigen::MatrixXd::Random(n, 3);
  Eigen::MatrixXd Y(n, 3);  // shares two directions with X, the third is new
  Y << X.col(0) + X.col(1), X.col(2), Eigen::VectorXd::Random(n);
  const Eigen::VectorXd cosines = stc::pgd::principalCosines(X, Y, f.A());
  ASSERT_EQ(cosines.size(), 3);
  EXPECT_NEAR(cosines[0], 1.0, 1e-12);
  EXPECT_NEAR(cosines[1], 1.0, 1e-12);
  EXPECT_LT(cosines[2], 0.9);
  const Eigen::MatrixXd U = X * Eigen::MatrixXd::Random(3, 7);
  EXPECT_LE(stc::pgd::projectionError(U, X, f.A()), 1e-7);  // sqrt of a round-off difference
  EXPECT_GT(stc::pgd::projectionError(U, Y, f.A()), 1e-3);
}
