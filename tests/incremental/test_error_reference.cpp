// The true-error measure with the Delassus operator computed lazily agrees with the whole-W measure,
// in 2D and 3D, and computes the columns of the nodes where the iterate differs only; the lazy
// columns do not depend on how their solves are chunked.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "fixtures/slab_scene.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/incremental/incremental_solver.hpp"

namespace {

// A LATIN run stopped early differs from the reference on the nodes it loads; so does the reference
// with its forces scaled (every loaded node) or perturbed on one node.
void expectLazyMatchesWhole(const stc::Scene& scene) {
  const stc::Problem problem = stc::buildProblem(scene);
  const stc::SolveResult ref = stc::solveIncremental(problem);
  ASSERT_TRUE(ref.summary.converged());
  auto factor = std::make_shared<const stc::CholmodFactor>(problem.stiffness_free, "K");
  const stc::ErrorReference whole(problem, *factor, stc::CondensedInterface::build(problem, *factor).delassus,
                                  ref.interface.lambda);
  const stc::ErrorReference lazy(problem, factor, ref.interface.lambda);
  Eigen::MatrixXd perturbed = ref.interface.lambda;
  const int loaded = static_cast<int>(problem.contact.size() / 2);
  perturbed(problem.contact.normalRow(loaded), problem.numSteps() - 1) += 1.0;
  for (const Eigen::MatrixXd& lambda :
       {Eigen::MatrixXd(1.01 * ref.interface.lambda), perturbed, Eigen::MatrixXd(ref.interface.lambda)}) {
    const double a = whole.relativeError(lambda), b = lazy.relativeError(lambda);
    EXPECT_NEAR(b, a, 1e-10 * a + 1e-14) << scene.name;
  }
  EXPECT_GT(lazy.nodesComputed(), 0);
  EXPECT_LT(lazy.nodesComputed(), problem.contact.size()) << "columns for the loaded nodes only";
  std::printf("[ measured ] %s: lazy measure computed the columns of %d of %d contact nodes\n", scene.name.c_str(),
              lazy.nodesComputed(), problem.contact.size());
}

}  // namespace

TEST(ErrorReference, LazyDelassusGivesTheSameErrorAsTheWholeOperator) {
  expectLazyMatchesWhole(stc::test::seedScene(31, 41));
  expectLazyMatchesWhole(stc::test::hemisphereScene(4, 21));
}

// Columns solved node by node (the smallest chunk) equal the dense Delassus operator's, held rows
// included: the chunked solves of ensure() change the blocking only.
TEST(LazyDelassus, ColumnsSolvedInChunksEqualTheWholeOperator) {
  for (const stc::Scene& scene :
       {stc::test::seedScene(31, 11), stc::test::hemisphereScene(3, 11), stc::test::slabScene(31, 11)}) {
    const stc::Problem problem = stc::buildProblem(scene);
    const stc::CholmodFactor factor(problem.stiffness_free, "K");
    Eigen::MatrixXd W = stc::CondensedInterface::build(problem, factor).delassus;
    stc::giveHeldRowsCompliance(problem.contact, W);
    stc::LazyDelassus lazy(problem, factor, 1.0);
    std::vector<int> every(problem.contact.size());
    for (int j = 0; j < problem.contact.size(); ++j) every[j] = problem.contact.size() - 1 - j;
    lazy.ensure(every);
    ASSERT_EQ(lazy.nodesComputed(), problem.contact.size());
    if (scene.name == "slab") ASSERT_FALSE(problem.contact.held_rows.empty()) << "the slab holds rows along z";
    const int d = problem.contact.dimension;
    double worst = 0.0;
    for (int j = 0; j < problem.contact.size(); ++j)
      for (int a = 0; a < d; ++a) worst = std::max(worst, (lazy.column(j, a) - W.col(d * j + a)).cwiseAbs().maxCoeff());
    EXPECT_LE(worst, 1e-12 * W.cwiseAbs().maxCoeff()) << scene.name;
  }
}
