// reactions.csv's resultant columns (src/io/contact_tables.hpp): the contact force on the body in the
// global frame, Σ_i λ_n,i n_i + λ_t,i τ_i, beside the sums of each node's own-frame components.
#include "stcontact/io/contact_tables.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"

namespace {

// On the seed's flat obstacle (n = e_y, τ = (n_y, −n_x) = e_x) the resultant is the own-frame sums.
TEST(ReactionTable, OnAPlaneTheResultantIsTheNormalAndTangentialSums) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 11));
  const stc::SolveResult result = stc::solveIncremental(problem);
  const stc::ReactionTable table = stc::reactionTable(problem, result);
  ASSERT_EQ(table.force.rows(), 2);
  ASSERT_EQ(table.force.cols(), problem.numSteps());
  const double scale = *std::max_element(table.normal_force.begin(), table.normal_force.end());
  ASSERT_GT(scale, 0.0);
  for (int k = 0; k < problem.numSteps(); ++k) {
    EXPECT_NEAR(table.force(0, k), table.tangential_force[k], 1e-12 * scale) << k;
    EXPECT_NEAR(table.force(1, k), table.normal_force[k], 1e-12 * scale) << k;
  }
  std::ostringstream csv;
  stc::writeReactionsCsv(csv, problem, result);
  const std::string header = csv.str().substr(0, csv.str().find('\n'));
  EXPECT_EQ(header, "step,t,normal_force,tangential_force,contact_xmin,contact_xmax,n_contact,n_slip,force_x,force_y");
}

}  // namespace
