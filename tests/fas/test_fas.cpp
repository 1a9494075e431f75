// Two-level FAS (seed §4): reduces to LATIN with an empty basis, converges in a few cycles when
// the basis spans the solution, coarse operator SPD, agreement with the incremental solver.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>

#include "fas/seed_fas_fixture.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/fas/aposteriori/fixed_basis_provider.hpp"
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/fas/fas_solver.hpp"
#include "stcontact/fas/residual_vectors.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/linalg/dense_decompositions.hpp"

namespace {

const stc::test::SeedFas& fixture() { return stc::test::seedFas(); }

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

}  // namespace

TEST(Fas, EmptyBasisGivesExactlyLatinsIterates) {
  const auto& f = fixture();
  stc::latin::GlobalStage g1(f.problem), g2(f.problem);
  g1.keepDisplacements(true);
  stc::fas::FixedBasisProvider empty(Eigen::MatrixXd(f.problem.numFreeDofs(), 0), 0, g1, f.problem.contact.B);
  stc::fas::FasOptions fas;
  fas.stop.max_iterations = 40;
  fas.stop.tolerance = 1e-14;
  stc::latin::LatinOptions latin;
  latin.stop.max_iterations = 40;
  latin.stop.tolerance = 1e-14;
  // LATIN starts from s = 0 with a local stage; FAS's fine level does the same.
  const auto a = stc::fas::solveFas(f.problem, g1, empty, fas, {}, "fas");
  const auto b = stc::latin::solveLatinWith(f.problem, g2, latin, {}, "latin");
  ASSERT_EQ(a.summary.history.size(), b.summary.history.size());
  for (std::size_t i = 0; i < a.summary.history.size(); ++i)
    EXPECT_EQ(a.summary.history[i].indicator, b.summary.history[i].indicator) << "relaxation " << i + 1;
  EXPECT_EQ(a.interface.lambda, b.interface.lambda);
}

TEST(Fas, CoarseOperatorIsIdentityHenceSymmetricPositiveDefinite) {
  const auto& f = fixture();
  stc::latin::GlobalStage g(f.problem);
  const stc::fas::CoarseSpace space(f.leadingModes(8), g.matrix(), f.problem.contact.B);
  EXPECT_EQ(space.rank(), 8);
  EXPECT_LE(space.orthonormalityDefect(g.matrix()), 1e-12);
  // A dependent vector is dropped rather than breaking the orthonormalisation.
  Eigen::MatrixXd twice(f.problem.numFreeDofs(), 16);
  twice << f.leadingModes(8), f.leadingModes(8);
  EXPECT_EQ(stc::fas::CoarseSpace(twice, g.matrix(), f.problem.contact.B).rank(), 8);
}

TEST(Fas, BasisSpanningTheSolutionConvergesInFewCycles) {
  // Every left singular vector of the converged history (rank ≤ m = 41) plus enough residual
  // vectors to span the current iterate too: then the exact correction u_ref − ũ lies in the coarse
  // space, and the coarse iterations (LATIN restricted to that space, cheap: many of them) reach
  // it in a few cycles: 16 fine relaxations instead of LATIN's 77 at 1e-8 (measured).
  const auto& f = fixture();
  stc::latin::GlobalStage g(f.problem);
  g.keepDisplacements(true);
  const stc::linalg::Svd svd =
      stc::linalg::singularValueDecomposition(f.u_ref, stc::linalg::SvdMethod::jacobi, stc::linalg::kThinU);
  const int rank = static_cast<int>((svd.values.array() > 1e-12 * svd.values[0]).count());
  stc::fas::FixedBasisProvider provider(svd.U.leftCols(rank), f.problem.numSteps(), g, f.problem.contact.B);
  stc::fas::FasOptions options;
  options.stop.tolerance = 1e-8;
  options.coarse_iterations = 300;
  options.start = stc::fas::CoarseStart::InterfaceMismatch;  // exact when the space is complete
  const auto result = stc::fas::solveFas(f.problem, g, provider, options, {}, "fas");
  ASSERT_TRUE(result.summary.converged()) << result.summary.message;
  EXPECT_LE(result.summary.relaxations, 20);  // measured: 16 (8 cycles of ν1 = ν2 = 1)
  stc::latin::GlobalStage g2(f.problem);
  stc::latin::LatinOptions latin;
  latin.stop.tolerance = 1e-8;
  EXPECT_GE(stc::latin::solveLatin(f.problem, latin).summary.iterations, 4 * result.summary.relaxations);  // 77
}

TEST(Fas, FineResultAgreesWithIncremental) {
  // SVD modes + residual vectors, ν1 = ν2 = 2 (ν = 1 stalls near 1e-4, as the seed's Fig. 5 reports).
  // Tolerance 1e-9 on the error estimate keeps the forces within 1e-6 of the reference.
  const auto& f = fixture();
  stc::latin::GlobalStage g(f.problem);
  g.keepDisplacements(true);
  stc::fas::FixedBasisProvider provider(f.leadingModes(8), 10, g, f.problem.contact.B);
  stc::fas::FasOptions options;
  options.stop.tolerance = 1e-9;
  options.pre_relaxations = options.post_relaxations = 2;
  const auto result = stc::fas::solveFas(f.problem, g, provider, options, {}, "fas");
  ASSERT_TRUE(result.summary.converged()) << result.summary.message;
  EXPECT_LE(relativeDifference(result.interface.lambda, f.reference.interface.lambda), 1e-6);
  EXPECT_GT(result.summary.history.back().rank, 8);  // fixed modes + residual vectors
}

TEST(ResidualVectors, SpanWhatTheBasisMisses) {
  // ũ of exact rank 3 with one of its directions already in the basis: two residual vectors
  // recover the rest exactly.
  const auto& f = fixture();
  stc::latin::GlobalStage g(f.problem);
  const Eigen::MatrixXd modes = f.leadingModes(3);
  const Eigen::MatrixXd time = Eigen::MatrixXd::Random(3, f.problem.numSteps());
  const Eigen::MatrixXd u = modes * time;
  const stc::fas::CoarseSpace fixed(modes.leftCols(1), g.matrix(), f.problem.contact.B);
  const Eigen::MatrixXd res = stc::fas::residualVectors(u, fixed.basis(), g.matrix(), 5);
  EXPECT_EQ(res.cols(), 2);
  Eigen::MatrixXd all(u.rows(), 3);
  all << fixed.basis(), res;
  const Eigen::MatrixXd Q = stc::linalg::orthonormalColumns(all);
  const Eigen::MatrixXd projected = Q * (Q.transpose() * u);
  EXPECT_LE((projected - u).norm(), 1e-10 * u.norm());
}

namespace {
// The seed's plain cycle (i_C = 15 coarse iterations without Anderson mixing, strict safeguard θ = 1),
// on which the safeguard's tests below were measured, unless `defaults` asks for FasOptions' own
// (θ from `growth` when given).
stc::SolveResult solveWithFixedBasis(int modes, int residual_vectors, bool safeguard, bool adapt = true,
                                     bool defaults = false, std::optional<double> growth = std::nullopt) {
  const auto& f = fixture();
  stc::latin::GlobalStage g(f.problem);
  g.keepDisplacements(true);
  stc::fas::FixedBasisProvider provider(f.leadingModes(modes), residual_vectors, g, f.problem.contact.B);
  stc::fas::FasOptions options;
  if (!defaults) {
    options.coarse_iterations = 15;
    options.coarse_anderson = 0;
    options.safeguard_growth = 1.0;
  }
  if (growth) options.safeguard_growth = growth;
  options.stop.tolerance = 1e-8;
  options.stop.max_iterations = 400;
  options.safeguard = safeguard;
  options.adapt_coarse_iterations = adapt;
  return stc::fas::solveFas(f.problem, g, provider, options, {}, "fas");
}
}  // namespace

TEST(Fas, SafeguardTurnsTheTwoCycleOfAPoorCoarseSpaceIntoConvergence) {
  // 2 SVD modes + 2 residual vectors, ν1 = ν2 = 1: the plain cycle locks into a 2-cycle (coarse
  // step up, relaxation down) far from the solution (measured: η ≈ 0.09, forces 150% off after 400
  // relaxations). With the safeguard the bad corrections are undone: it converges, in no more
  // relaxations than LATIN, forces within 1e-6 of the incremental solution.
  const auto& f = fixture();
  const auto plain = solveWithFixedBasis(2, 2, false);
  EXPECT_FALSE(plain.summary.converged());
  EXPECT_GT(relativeDifference(plain.interface.lambda, f.reference.interface.lambda), 1e-2);
  const auto guarded = solveWithFixedBasis(2, 2, true, false);
  ASSERT_TRUE(guarded.summary.converged()) << guarded.summary.message;
  EXPECT_NE(guarded.summary.message.find("coarse corrections rejected"), std::string::npos);
  EXPECT_LE(relativeDifference(guarded.interface.lambda, f.reference.interface.lambda), 1e-6);
  stc::latin::LatinOptions latin;
  latin.stop.tolerance = 1e-8;
  EXPECT_LE(guarded.summary.relaxations, stc::latin::solveLatin(f.problem, latin).summary.relaxations);
}

TEST(Fas, DefaultSettingsAlsoConvergeWithAPoorCoarseSpace) {
  // The defaults (i_C = 8 with Anderson depth 2; θ = 1.5, the 2D growth of a coarse space that is not
  // anticipated, fas::defaultSafeguardGrowth) on the same poor coarse space: the looser safeguard still
  // breaks the 2-cycle and the solve reaches the incremental solution (measured: 99 relaxations, 8
  // corrections rejected, against LATIN's 91: a space that holds little gains nothing from a
  // stronger coarse solve).
  const auto& f = fixture();
  const auto result = solveWithFixedBasis(2, 2, true, true, true);
  ASSERT_TRUE(result.summary.converged()) << result.summary.message;
  EXPECT_LE(relativeDifference(result.interface.lambda, f.reference.interface.lambda), 1e-6);
  std::printf("[ measured ] poor coarse space, default FAS settings: %d relaxations (%s)\n",
              result.summary.relaxations, result.summary.message.c_str());
}

TEST(Fas, PayBackRuleBreaksTheTwoCycleUnderALooseGrowth) {
  // θ = 5, fas-apriori's 2D growth, on the same poor coarse space: its corrections raise η less than
  // 5 times and are kept, so only the pay-back rule (a kept raise that does not pay back within its
  // cycle makes the next correction judged with θ = 1; fas/fas_solver.cpp) breaks the 2-cycle
  // (measured: 101 relaxations; without the rule the solve stayed in the 2-cycle until the cap of
  // 400, and θ = 3 converged in 101).
  const auto& f = fixture();
  const auto result = solveWithFixedBasis(2, 2, true, true, true, 5.0);
  ASSERT_TRUE(result.summary.converged()) << result.summary.message;
  EXPECT_NE(result.summary.message.find("coarse corrections rejected"), std::string::npos);
  EXPECT_LE(relativeDifference(result.interface.lambda, f.reference.interface.lambda), 1e-6);
  std::printf("[ measured ] poor coarse space, θ = 5: %d relaxations (%s)\n", result.summary.relaxations,
              result.summary.message.c_str());
}

TEST(Fas, AdaptedCoarseIterationsStillConvergeWithAPoorCoarseSpace) {
  // The same poor coarse space with i_C following the safeguard's verdicts (FasOptions::
  // adapt_coarse_iterations): rejections halve i_C, which the message reports; the solve still
  // reaches the incremental solution. Here it costs relaxations (measured: 99 against 89 with i_C
  // fixed, 9 rejections each, i_C ends at 5): weaker corrections of a space that holds little.
  const auto& f = fixture();
  const auto adapted = solveWithFixedBasis(2, 2, true, true);
  ASSERT_TRUE(adapted.summary.converged()) << adapted.summary.message;
  EXPECT_NE(adapted.summary.message.find("i_C ended at "), std::string::npos) << adapted.summary.message;
  EXPECT_LE(relativeDifference(adapted.interface.lambda, f.reference.interface.lambda), 1e-6);
  const auto fixed = solveWithFixedBasis(2, 2, true, false);
  std::printf("[ measured ] poor coarse space, plain cycle: i_C adapted %d relaxations (%s); fixed %d (%s)\n",
              adapted.summary.relaxations, adapted.summary.message.c_str(), fixed.summary.relaxations,
              fixed.summary.message.c_str());
}

TEST(Fas, SafeguardLeavesAGoodCoarseSpaceUntouched) {
  // 8 modes + 10 residual vectors: no correction raises the indicator, so no rejection, and the
  // iterates are exactly those of the plain cycle.
  const auto plain = solveWithFixedBasis(8, 10, false);
  const auto guarded = solveWithFixedBasis(8, 10, true);
  ASSERT_EQ(plain.summary.history.size(), guarded.summary.history.size());
  for (std::size_t i = 0; i < plain.summary.history.size(); ++i)
    EXPECT_EQ(plain.summary.history[i].indicator, guarded.summary.history[i].indicator) << "relaxation " << i + 1;
  EXPECT_EQ(guarded.summary.message.find("rejected"), std::string::npos);
}

namespace {
std::string validationMessage(const auto& options) {
  try {
    options.validate();
  } catch (const stc::InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(FasOptions, ValidateNamesFieldValueAndRuleWithIntegersAsIntegers) {
  stc::fas::FasOptions options;
  options.max_skip = 0;
  EXPECT_EQ(validationMessage(options), "FAS option max_skip = 0: must be >= 1");
}

TEST(AprioriBasisOptions, ValidateNamesTheFieldAndRefusesAnEmptyCoarseSpace) {
  stc::fas::AprioriBasisOptions options;
  EXPECT_EQ(validationMessage(options), "");
  options.modes = -1;
  EXPECT_EQ(validationMessage(options), "a priori basis option pgd_max_modes = -1: must be >= 0");
  options = {};
  options.increment_modes = -2;
  EXPECT_EQ(validationMessage(options), "a priori basis option pgd_increment_modes = -2: must be >= 0");
  options.modes = options.increment_modes = 0;
  EXPECT_EQ(validationMessage(options),
            "a priori basis option pgd_max_modes + pgd_increment_modes = 0: must be >= 1 (an empty coarse space)");
}

TEST(FasOptions, RefusesANegativeAndersonDepthAndASafeguardGrowthBelowOne) {
  stc::fas::FasOptions options;
  options.validate();  // the defaults
  options.coarse_anderson = -1;
  EXPECT_THROW(options.validate(), stc::InputError);
  options.coarse_anderson = 0;
  options.safeguard_growth = 0.9;
  EXPECT_THROW(options.validate(), stc::InputError);
}
