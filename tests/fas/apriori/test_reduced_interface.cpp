// `fas-apriori` on its contact zone (fas/apriori/reduced_interface.hpp): the zone comes from the
// prescribed motion or a first relaxation, the nodes left out are checked open, the result lifted to
// the whole interface is an equilibrated iterate of the whole problem (the lift to the tolerance),
// and a zone that misses contact nodes is completed by the check; a round that does not converge
// within its half of the cap hands its iterate to the whole interface.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "fixtures/seed_scene.hpp"
#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/fas/apriori/reduced_interface.hpp"
#include "stcontact/fas/apriori/zone_rounds.hpp"
#include "stcontact/problem/prescribed_reach.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

const stc::test::StrategyFixture& fixture() {
  static const stc::test::StrategyFixture f(stc::test::seedScene(31, 41));
  return f;
}

stc::SolverSpec specAt(double tolerance, bool reduce) {
  stc::SolverSpec spec = fixture().scene.solver;
  spec.setTolerance(tolerance);
  spec.fas_apriori.zone.enabled = reduce;
  return spec;
}

// The nodes that carry no force at any instant of `lambda` (the nodes a solve left out, and
// open nodes of the zone).
std::vector<int> unloadedNodes(const stc::ContactInterface& contact, const Eigen::MatrixXd& lambda) {
  std::vector<int> nodes;
  const int d = contact.dimension;
  for (int i = 0; i < contact.size(); ++i)
    if (lambda.middleRows(d * i, d).cwiseAbs().maxCoeff() == 0.0) nodes.push_back(i);
  return nodes;
}

// The lifted result must be an equilibrated iterate of the whole problem: v = B u with
// K_ff u = f + Bᵀ λ at every instant. The mismatch max_k ‖(B u_k − v_k) on some rows‖ / max_k ‖B u_k‖
// (every tenth instant, on the history's scale: an unloaded instant's own is zero), on the rows of
// the loaded nodes (solved on the zone) and on every row (the nodes left out come from the separated
// displacement history, pgd::ResponseBasis::displacementOn).
struct Mismatch {
  double loaded = 0.0, all = 0.0;
};
Mismatch equilibriumMismatch(const stc::Problem& problem, const stc::CholmodFactor& K, const stc::InterfaceHistory& s) {
  const stc::ContactInterface& contact = problem.contact;
  const std::vector<int> loaded =
      stc::rowsOfNodes(contact.dimension, stc::otherNodes(contact.size(), unloadedNodes(contact, s.lambda)));
  Mismatch worst;
  double scale = 0.0;
  for (int k = 0; k < problem.numSteps(); k += 10) {
    const Eigen::VectorXd u = K.solve(Eigen::MatrixXd(problem.load(k) + contact.B.transpose() * s.lambda.col(k)));
    const Eigen::VectorXd v = contact.B * u, mismatch = v - s.v.col(k);
    worst.loaded = std::max(worst.loaded, mismatch(loaded).norm());
    worst.all = std::max(worst.all, mismatch.norm());
    scale = std::max(scale, v.norm());
  }
  scale = std::max(scale, 1e-300);
  return {worst.loaded / scale, worst.all / scale};
}

// The loaded nodes' rows in equilibrium to the sparse solves' accuracy; the nodes left out, lifted
// through a history truncated to what the estimate leaves of the tolerance
// (pgd::ResponseBasis::displacementOn), within the tolerance τ = 1e-6 of the history's scale.
void expectEquilibrium(const stc::Problem& problem, const stc::CholmodFactor& K, const stc::InterfaceHistory& s) {
  ASSERT_LT(unloadedNodes(problem.contact, s.lambda).size(), static_cast<size_t>(problem.contact.size()));
  const Mismatch mismatch = equilibriumMismatch(problem, K, s);
  EXPECT_LE(mismatch.loaded, 1e-8);
  EXPECT_LE(mismatch.all, 1e-6);
}

}  // namespace

TEST(ErrorOnRows, MeasuresTheForcesOfTheRowsLeftOutAsZero) {
  const auto& f = fixture();
  const Eigen::MatrixXd& lambda = f.incremental.interface.lambda;
  const std::vector<int> rows = {0, 1, 2, 3, 10, 11};
  const stc::fas::ErrorOnRows measure(f.reference, rows, f.problem.contact.rows());
  Eigen::MatrixXd whole = Eigen::MatrixXd::Zero(lambda.rows(), lambda.cols());
  whole(rows, Eigen::all) = lambda(rows, Eigen::all);
  EXPECT_DOUBLE_EQ(measure.relativeError(lambda(rows, Eigen::all)), f.reference.relativeError(whole));
  EXPECT_TRUE(measure.defined());
}

// The default path: the seed is driven by a prescribed motion, so the zone is the nodes within its
// reach, found before any solve; it holds the contact nodes, the rest are left out and found open. The answer is the whole problem's: true error at most the tolerance, nodes left out
// unloaded and clear of the obstacle, the zone's iterate in equilibrium to the sparse solves' accuracy, the lift to the tolerance.
TEST(ReducedInterface, SolvesTheWholeProblemOnItsContactZone) {
  const auto& f = fixture();
  stc::SolveInputs inputs;
  inputs.reference = &f.reference;
  const stc::SolveResult r = stc::solve(stc::strategyNamed("fas-apriori"), f.problem, specAt(1e-6, true), inputs);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_NE(r.summary.message.find("within reach of the prescribed motion"), std::string::npos) << r.summary.message;
  ASSERT_TRUE(r.summary.error.has_value());
  EXPECT_LE(*r.summary.error, 1e-6);
  const stc::ContactInterface& contact = f.problem.contact;
  const std::vector<int> unloaded = unloadedNodes(contact, r.interface.lambda);
  EXPECT_GT(unloaded.size(), static_cast<size_t>(contact.size() / 3));
  std::cout << "[ measured ] " << unloaded.size() << " of " << contact.size() << " nodes unloaded; "
            << r.summary.message << "\n";
  for (int i : unloaded)
    EXPECT_GE((contact.initial_gap[i] + r.interface.v.row(contact.normalRow(i)).array()).minCoeff(), 0.0) << "node " << i;
  expectEquilibrium(f.problem, f.K, r.interface);
  // The counts add up.
  ASSERT_EQ(static_cast<int>(r.summary.history.size()), r.summary.iterations);
  EXPECT_EQ(r.summary.history.front().iteration, 1);
  EXPECT_EQ(r.summary.history.back().relaxations, r.summary.relaxations);
  EXPECT_EQ(r.interface_directions.rows(), contact.rows());
}

// Asked for the separated displacement (the fields of a run), the solve takes the nodes left out from
// it: their v is its trace B u_ρ, with no solve of their own (fas/apriori/single_solve.cpp). Without
// it the lift solves through the rank of the zone's history, at most one solve per mode of the same
// truncation; with it, before, each mode was solved twice. Same iteration either way.
TEST(ReducedInterface, TheNodesLeftOutAreTheTraceOfTheHeldDisplacementWithoutSolvesOfTheirOwn) {
  const auto& f = fixture();
  stc::SolveInputs plain, with_fields;
  with_fields.separated_displacement = true;
  const stc::SolveResult r0 = stc::solve(stc::strategyNamed("fas-apriori"), f.problem, specAt(1e-6, true), plain);
  const stc::SolveResult r1 = stc::solve(stc::strategyNamed("fas-apriori"), f.problem, specAt(1e-6, true), with_fields);
  ASSERT_TRUE(r0.summary.converged() && r1.summary.converged()) << r1.summary.message;
  ASSERT_TRUE(r1.displacement.held);
  EXPECT_EQ(r1.summary.iterations, r0.summary.iterations);
  const long modes = r1.displacement.modes.cols(), extra = r1.summary.sparseSolves() - r0.summary.sparseSolves();
  std::cout << "[ measured ] sparse solves " << r0.summary.sparseSolves() << " without the fields, "
            << r1.summary.sparseSolves() << " with them (" << modes << " modes)\n";
  EXPECT_GE(extra, 0);
  EXPECT_LT(extra, modes);
  // Every unloaded node's v is the held displacement's trace: exactly on the nodes left out, within
  // the tolerance on the zone's open nodes (the iteration's v, in equilibrium to τ).
  const stc::ContactInterface& contact = f.problem.contact;
  const std::vector<int> rows = stc::rowsOfNodes(contact.dimension, unloadedNodes(contact, r1.interface.lambda));
  ASSERT_FALSE(rows.empty());
  const Eigen::MatrixXd trace = (contact.B * r1.displacement.modes) * r1.displacement.time;
  const double scale = trace.cwiseAbs().maxCoeff();
  int exact = 0;
  for (int row : rows) {
    const double gap = (trace.row(row) - r1.interface.v.row(row)).cwiseAbs().maxCoeff();
    EXPECT_LE(gap, 1e-6 * scale) << "row " << row;
    exact += gap <= 1e-14 * scale;
  }
  EXPECT_GT(exact, static_cast<int>(rows.size()) / 2);
  expectEquilibrium(f.problem, f.K, r1.interface);
}

// The prediction's claim on the seed: every node that the reference solution (the incremental
// solver) closes at some instant is within reach of the prescribed motion.
TEST(ReducedInterface, TheZoneWithinReachHoldsEveryNodeTheReferenceCloses) {
  const auto& f = fixture();
  const auto W = stc::prescribedTranslation(f.problem);
  ASSERT_TRUE(W.has_value());
  const std::vector<int> reach = stc::nodesWithinReach(f.problem.contact, *W, 0.0);
  const stc::ContactInterface& contact = f.problem.contact;
  int closed = 0;
  for (int i = 0; i < contact.size(); ++i) {
    if (f.incremental.interface.lambda.row(contact.normalRow(i)).maxCoeff() <= 0.0) continue;
    ++closed;
    EXPECT_TRUE(std::binary_search(reach.begin(), reach.end(), i)) << "node " << i << " closes";
  }
  EXPECT_GT(closed, 0);
  std::cout << "[ measured ] " << closed << " nodes close, " << reach.size() << " within reach, of "
            << contact.size() << "\n";
}

// With an applied force the reach of the loading is not known before a solve: the zone is the first
// relaxation's, and the history counts that relaxation (on the whole interface) as its iteration 1.
TEST(ReducedInterface, WithAnAppliedForceTheZoneComesFromAFirstRelaxation) {
  stc::Scene scene = stc::test::seedScene(31, 41);
  scene.loads.push_back({"arc", stc::Component::Y, {{0.0, 1.0}, {0.0, 1.0}}});  // 1 N up, spread on the arc
  const stc::test::StrategyFixture pushed(scene);
  stc::SolverSpec spec = pushed.scene.solver;
  spec.setTolerance(1e-6);
  spec.fas_apriori.zone.enabled = true;
  stc::SolveInputs inputs;
  inputs.reference = &pushed.reference;
  const stc::SolveResult r = stc::solve(stc::strategyNamed("fas-apriori"), pushed.problem, spec, inputs);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_NE(r.summary.message.find("first relaxation on all"), std::string::npos) << r.summary.message;
  ASSERT_TRUE(r.summary.error.has_value());
  EXPECT_LE(*r.summary.error, 1e-6);
  ASSERT_GE(r.summary.history.size(), 2u);
  EXPECT_EQ(r.summary.history[0].relaxations, 1);
  EXPECT_EQ(r.summary.history[1].iteration, 2);
  EXPECT_EQ(r.summary.history.back().relaxations, r.summary.relaxations);
  std::cout << "[ measured ] " << r.summary.message << "\n";
}

// A zone that misses contact nodes (the node nearest the obstacle alone): the nodes left out
// penetrate after the first restricted solve, join the zone, and a later round ends at the whole
// problem's solution.
TEST(ReducedInterface, ACheckOfTheNodesLeftOutCompletesAZoneThatMissesContact) {
  const auto& f = fixture();
  stc::SolveInputs inputs;
  inputs.reference = &f.reference;
  stc::fas::ZoneStart from;  // from s = 0
  const int nearest = f.problem.contact.size() / 2;  // the half-disc's lowest arc node
  const stc::SolveResult r = stc::fas::solveAprioriOnZone(f.problem, specAt(1e-6, true).fas_apriori, inputs, {nearest}, from);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_NE(r.summary.message.find("penetrating"), std::string::npos) << r.summary.message;
  std::cout << "[ measured ] " << r.summary.message << "\n";
  ASSERT_TRUE(r.summary.error.has_value());
  EXPECT_LE(*r.summary.error, 1e-6);
  expectEquilibrium(f.problem, f.K, r.interface);
}

// The reduction changes the iteration, not the answer: both paths end within the tolerance of the
// same reference, so (triangle inequality in the energy norm) within about twice it of each other.
TEST(ReducedInterface, AgreesWithTheWholeInterface) {
  const auto& f = fixture();
  stc::SolveInputs inputs;
  inputs.reference = &f.reference;
  const stc::SolveResult reduced = stc::solve(stc::strategyNamed("fas-apriori"), f.problem, specAt(1e-6, true), inputs);
  const stc::SolveResult whole = stc::solve(stc::strategyNamed("fas-apriori"), f.problem, specAt(1e-6, false), inputs);
  ASSERT_TRUE(reduced.summary.converged() && whole.summary.converged());
  EXPECT_EQ(whole.summary.message.find("solved on"), std::string::npos);
  const stc::ErrorReference against_whole(f.problem, f.K, stc::CondensedInterface::build(f.problem, f.K).delassus,
                                          whole.interface.lambda);
  EXPECT_LE(against_whole.relativeError(reduced.interface.lambda), 2.1e-6);
  EXPECT_LT(reduced.summary.relaxations, whole.summary.relaxations);
  std::cout << "[ measured ] relaxations, reduced " << reduced.summary.relaxations << ", whole "
            << whole.summary.relaxations << "\n";
}

// A restricted round gets half of the iterations left (here 4 of 8, too few for τ = 1e-6: it takes
// 7); the whole interface then goes on from where it stopped, not from the first start, and stops
// at the cap too (its 4 relaxations are not enough either). Its first relaxation's true error is far
// below the start's (0.052 against 0.39), though above the round's last (7.7e-4): a started stage's
// first solve projects its right-hand side to a share of itself, γ = 5 %, before any gap is known
// (ControlledStageOptions::gap_share).
TEST(ReducedInterface, ARoundCutShortByTheCapHandsItsIterateToTheWholeInterface) {
  const auto& f = fixture();
  const int cap = 8, half = cap / 2;
  stc::SolverSpec spec = specAt(1e-6, true);
  spec.fas_apriori.fas.stop.max_iterations = cap;
  stc::SolveInputs inputs;
  inputs.reference = &f.reference;
  const stc::SolveResult r = stc::solve(stc::strategyNamed("fas-apriori"), f.problem, spec, inputs);
  std::cout << "[ measured ] " << r.summary.message << "\n";
  EXPECT_NE(r.summary.message.find("max_iterations, from where it stopped"), std::string::npos) << r.summary.message;
  // The whole interface too stops at the cap: the reason names the solve's, not the round's share.
  EXPECT_EQ(r.summary.termination, stc::Termination::MaxIterations);
  EXPECT_EQ(r.summary.message.rfind("iteration limit " + std::to_string(cap) + " reached", 0), 0u) << r.summary.message;
  const std::vector<stc::IterationRecord>& h = r.summary.history;
  ASSERT_GT(h.size(), static_cast<std::size_t>(half));
  ASSERT_TRUE(h[0].error && h[half - 1].error && h[half].error);
  std::cout << "[ measured ] true error: first " << *h[0].error << ", the round's last " << *h[half - 1].error
            << ", the whole interface's first " << *h[half].error << "\n";
  EXPECT_LT(*h[half - 1].error, 1e-2 * *h[0].error);
  EXPECT_LT(*h[half].error, 0.25 * *h[0].error);
}

// A round on the whole interface keeps the whole of the iterations left, also where the search
// direction grows with the zone (ReducedInterfaceOptions::search_growth: 101 nodes in 2D, k × 1.26,
// a problem of its own). Here the zone is the whole interface (zone_whole_share = 0) and the solve
// takes 15 relaxations to τ = 1e-6; with a cap of 16 a round that got half of it stopped at 8.
TEST(ReducedInterface, ARoundOnTheWholeInterfaceWithAGrownSearchDirectionKeepsTheWholeCap) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(101, 41));
  stc::SolverSpec spec = stc::test::seedScene(101, 41).solver;
  spec.setTolerance(1e-6);
  spec.fas_apriori.zone.whole_share = 0.0;
  spec.fas_apriori.fas.stop.max_iterations = 16;
  ASSERT_GT(spec.fas_apriori.zone.searchScaleOn(problem.contact.size(), problem.dimension), 1.0);
  const stc::SolveResult r = stc::solve(stc::strategyNamed("fas-apriori"), problem, spec, {});
  EXPECT_NE(r.summary.message.find("101 of 101 contact nodes"), std::string::npos) << r.summary.message;
  EXPECT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_GT(r.summary.relaxations, 8) << r.summary.message;
}
