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
// included: the chunked solves of ensure() change the blocking only; ensure() says after each chunk
// how many of the missing nodes are done.
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
    std::vector<int> done_after_chunk;
    lazy.ensure(every, [&](int done, int missing) {
      EXPECT_EQ(missing, problem.contact.size());
      done_after_chunk.push_back(done);
    });
    ASSERT_EQ(lazy.nodesComputed(), problem.contact.size());
    ASSERT_EQ(static_cast<int>(done_after_chunk.size()), problem.contact.size()) << "one node per chunk";
    for (std::size_t c = 0; c < done_after_chunk.size(); ++c) EXPECT_EQ(done_after_chunk[c], static_cast<int>(c) + 1);
    if (scene.name == "slab") ASSERT_FALSE(problem.contact.held_rows.empty()) << "the slab holds rows along z";
    const int d = problem.contact.dimension;
    double worst = 0.0;
    for (int j = 0; j < problem.contact.size(); ++j)
      for (int a = 0; a < d; ++a) worst = std::max(worst, (lazy.column(j, a) - W.col(d * j + a)).cwiseAbs().maxCoeff());
    EXPECT_LE(worst, 1e-12 * W.cwiseAbs().maxCoeff()) << scene.name;
  }
}
