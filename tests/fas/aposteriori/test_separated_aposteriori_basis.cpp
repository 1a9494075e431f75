// The a posteriori basis on the separated fine level (fas/aposteriori/separated_aposteriori_basis.hpp):
// its coarse space is the fixed modes and the leading energy singular vectors of what they miss of the
// separated iterate, computed from small factors as an explicit n_free × m computation gives them;
// `fas-aposteriori` on that fine level converges to the incremental solution like `fas-apriori`.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>

#include "fas/seed_fas_fixture.hpp"
#include "stcontact/fas/aposteriori/separated_aposteriori_basis.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/pgd/separated_history.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

const stc::test::SeedFas& fixture() { return stc::test::seedFas(); }

// A separated global stage after three LATIN iterations from s = 0, and the last local stage ŝ.
struct Iterated {
  stc::pgd::ControlledGlobalStage stage{fixture().problem, {}};
  stc::InterfaceHistory s, hat = stc::InterfaceHistory::zeros(fixture().problem.contact, fixture().problem.numSteps());
  Iterated() {
    for (int i = 0; i < 3; ++i) {
      stage.solve(hat, s);
      stc::latin::localStage(fixture().problem.contact, s, hat);
    }
  }
  /// ũ = [U_F X] Θ of the last solve, n_free × m (explicit: for the checks only).
  Eigen::MatrixXd displacements() const {
    const stc::pgd::ResponseBasis& basis = stage.basis();
    const Eigen::Index s_cols = basis.loadResponses().cols() + basis.size();
    const Eigen::MatrixXd Phi = stc::pgd::spatialModes(basis, Eigen::MatrixXd::Identity(s_cols, s_cols));
    return Phi * stc::pgd::historyFactor(basis, stage.coordinates());
  }
};

// min over the sign of ‖a ∓ b‖ / ‖b‖.
double distanceUpToSign(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return std::min((a - b).norm(), (a + b).norm()) / b.norm();
}

}  // namespace

TEST(SeparatedAposterioriBasis, HoldsTheFixedModesAndSpansTheIterate) {
  const auto& f = fixture();
  const Iterated it;
  const Eigen::SparseMatrix<double>& B = f.problem.contact.B;
  stc::fas::SeparatedAposterioriProvider provider(f.leadingModes(4), 200, it.stage, B);
  const stc::fas::CoarseSpace space = provider.coarseSpace(it.hat);
  const stc::fas::CoarseSpace fixed(f.leadingModes(4), it.stage.matrix(), B);
  ASSERT_GT(space.rank(), 4);
  EXPECT_EQ(space.interface().leftCols(4), fixed.interface());
  // With every residual vector the space holds ũ: its traces B ũ lie in the span of the traces.
  const Eigen::MatrixXd Bu = B * it.displacements();
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(space.interface()).householderQ() *
                            Eigen::MatrixXd::Identity(space.interface().rows(), space.rank());
  EXPECT_LE((Bu - Q * (Q.transpose() * Bu)).norm(), 1e-8 * Bu.norm());
}

TEST(SeparatedAposterioriBasis, ResidualVectorsAreTheLeadingEnergySingularVectorsOfWhatTheModesMiss) {
  // Explicitly: R = ũ − Y Yᵀ A ũ (Y the A-orthonormal fixed modes), the SVD of Lᵀ R (A = L Lᵀ), the
  // residual vectors W = L⁻ᵀ U; their traces B W must be the provider's, column by column.
  const auto& f = fixture();
  const Iterated it;
  const Eigen::SparseMatrix<double>& B = f.problem.contact.B;
  const Eigen::MatrixXd A = it.stage.matrix();
  const stc::fas::CoarseSpace fixed(f.leadingModes(3), it.stage.matrix(), B);
  const Eigen::MatrixXd u = it.displacements(), &Y = fixed.basis();
  const Eigen::MatrixXd R = u - Y * (Y.transpose() * (A * u));
  const Eigen::LLT<Eigen::MatrixXd> llt(A);
  const Eigen::MatrixXd Lt = llt.matrixU();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Lt * R, Eigen::ComputeThinU);
  const Eigen::VectorXd& sigma = svd.singularValues();
  ASSERT_GT(sigma[0] / sigma[1], 1.01);  // distinct: each vector is defined up to its sign
  ASSERT_GT(sigma[1] / sigma[2], 1.01);
  const Eigen::MatrixXd W = Lt.triangularView<Eigen::Upper>().solve(svd.matrixU().leftCols(3));
  const Eigen::MatrixXd expected = B * W;
  stc::fas::SeparatedAposterioriProvider provider(f.leadingModes(3), 3, it.stage, B);
  const stc::fas::CoarseSpace space = provider.coarseSpace(it.hat);
  ASSERT_EQ(space.rank(), 6);
  for (int j = 0; j < 3; ++j)
    EXPECT_LE(distanceUpToSign(space.interface().col(3 + j), expected.col(j)), 1e-6) << "residual vector " << j;
}

TEST(SeparatedAposterioriBasis, FasAposterioriOnTheSeparatedFineLevelAgreesWithIncremental) {
  static const stc::test::StrategyFixture f(stc::test::seedScene(31, 41));
  stc::SolverSpec spec = f.scene.solver;
  spec.setTolerance(1e-6);
  spec.fas_aposteriori.fine_level = stc::fas::AposterioriFineLevel::Separated;
  stc::SolveInputs inputs;
  inputs.reference = &f.reference;
  const stc::SolveResult separated = stc::solve(stc::Strategy::FasAposteriori, f.problem, spec, inputs);
  ASSERT_TRUE(separated.summary.converged()) << separated.summary.message;
  EXPECT_EQ(separated.summary.solver, "fas-aposteriori");
  ASSERT_TRUE(separated.summary.error);
  EXPECT_LE(*separated.summary.error, 1e-6);
  // fas-apriori's fine level: its reduced interface, and a sparse solve per new direction, not per instant.
  EXPECT_NE(separated.summary.message.find("solved on"), std::string::npos) << separated.summary.message;
  spec.fas_aposteriori.fine_level = stc::fas::AposterioriFineLevel::Full;
  const stc::SolveResult full = stc::solve(stc::Strategy::FasAposteriori, f.problem, spec, inputs);
  ASSERT_TRUE(full.summary.converged()) << full.summary.message;
  EXPECT_LT(separated.summary.sparseSolves(), full.summary.sparseSolves() / 4);
}
