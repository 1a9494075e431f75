// The incremental reference solver (src/incremental/incremental_solver.hpp): the contact law at every node
// and instant, equilibrium of the rebuilt fields, first contact where the kinematics put it, Coulomb
// sliding, agreement with an independent frictionless QP solver, options, Newton effort, failure
// paths; plus the contact-state classification and the contact-law check it is judged by.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <regex>

#include "fixtures/seed_scene.hpp"
#include "stcontact/contact/contact_state.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/incremental/reach_zone.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/solver/contact_law_check.hpp"

namespace {

using stc::test::seedScene;

struct Solved {
  stc::Problem problem;
  stc::SolveResult result;
};

Solved solve(const stc::Scene& scene, const stc::IncrementalOptions& options = {}) {
  Solved s{stc::buildProblem(scene), {}};
  s.result = stc::solveIncremental(s.problem, options);
  return s;
}

// The seed scene solved once per size (the solver is deterministic).
const Solved& solvedSeed(int arc_nodes, int steps) {
  static std::map<std::pair<int, int>, std::unique_ptr<Solved>> cache;
  auto& slot = cache[{arc_nodes, steps}];
  if (!slot) slot = std::make_unique<Solved>(solve(seedScene(arc_nodes, steps)));
  return *slot;
}

// The total over the instants, from the message's documented "<N> Newton iterations".
int newtonIterations(const stc::SolveSummary& summary) {
  std::smatch match;
  if (!std::regex_search(summary.message, match, std::regex("([0-9]+) Newton iterations"))) return -1;
  return std::stoi(match[1]);
}

// Instant of t = 0.2, where the drive has moved the body down by exactly g0 = 0.01.
int touchInstant(int steps) { return (steps - 1) / 5; }

double slipIncrement(const stc::InterfaceHistory& h, int i, int k) {
  return h.v(2 * i + 1, k) - (k > 0 ? h.v(2 * i + 1, k - 1) : 0.0);
}

// Per instant: states of the nodes, with the history's scales (as the writers classify them).
std::vector<stc::ContactState> states(const Solved& s, int k) {
  const auto& h = s.result.interface;
  const double force = h.lambda.cwiseAbs().maxCoeff(), length = h.v.cwiseAbs().maxCoeff();
  std::vector<stc::ContactState> out;
  for (int i = 0; i < s.problem.contact.size(); ++i)
    out.push_back(stc::classifyContact(h.lambda(2 * i, k), h.lambda(2 * i + 1, k), slipIncrement(h, i, k),
                                       s.problem.contact.friction, force, length));
  return out;
}

// The seed with a cyclic tangential drive and μ = 0.3: stick–slip transitions and slip reversals.
stc::Scene cyclicScene(int arc_nodes, int steps) {
  stc::Scene scene = seedScene(arc_nodes, steps);
  scene.contact.friction = 0.3;
  scene.dirichlet[0].history = {{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}, {0.0, 0.0, 0.02, -0.02, 0.02, -0.02}};
  return scene;
}

// Tolerance of the law check: the solver stops at ‖F‖∞ ≤ 1e-13 S_k (header), and each measure of
// checkContactLaw is such a residual divided by a history scale of the same size up to the spread of
// ρ over the nodes (diag W varies by ~4 on the seed) and of S_k over the instants; 1e-10 leaves three
// decades for that, while a wrong active set at any node violates the law by ≥ 1e-3 relative.
// Observed: ≤ 2e-15 on every scene here.
constexpr double kLawTolerance = 1e-10;

TEST(IncrementalSolver, SatisfiesContactLawAtEveryNodeAndInstant) {
  for (auto [arc_nodes, steps] : {std::pair{31, 41}, std::pair{101, 201}}) {
    const Solved& s = solvedSeed(arc_nodes, steps);
    ASSERT_TRUE(s.result.summary.converged()) << s.result.summary.message;
    const stc::ContactLawViolation v = stc::checkContactLaw(s.problem, s.result.interface);
    EXPECT_LE(v.max(), kLawTolerance) << "arc_nodes " << arc_nodes << ": penetration " << v.penetration
                                      << ", complementarity " << v.complementarity << ", cone " << v.cone
                                      << ", stick_slip " << v.stick_slip << ", direction " << v.slip_direction;
  }
}

TEST(IncrementalSolver, SatisfiesContactLawThroughStickSlipTransitionsAndReversals) {
  stc::Scene high_friction = seedScene(31, 41);
  high_friction.contact.friction = 0.6;
  for (const stc::Scene& scene : {high_friction, cyclicScene(31, 81)}) {
    const Solved s = solve(scene);
    ASSERT_TRUE(s.result.summary.converged()) << s.result.summary.message;
    EXPECT_LE(stc::checkContactLaw(s.problem, s.result.interface).max(), kLawTolerance);
    int stick = 0, slip = 0;
    for (int k = 0; k < s.problem.numSteps(); ++k)
      for (stc::ContactState c : states(s, k)) {
        stick += c == stc::ContactState::Stick;
        slip += c == stc::ContactState::Slip;
      }
    EXPECT_GT(stick, 0) << "the variant must exercise sticking nodes";
    EXPECT_GT(slip, 0) << "the variant must exercise slipping nodes";
  }
}

TEST(IncrementalSolver, RebuiltDisplacementsSatisfyEquilibriumAndInterfaceKinematics) {
  const Solved& s = solvedSeed(31, 41);
  const auto& h = s.result.interface;
  const stc::CholmodFactor factor(s.problem.stiffness_free, "K_ff");
  const Eigen::MatrixXd u = stc::freeDisplacements(s.problem, factor, h.lambda);
  const Eigen::MatrixXd contact_force = s.problem.contact.B.transpose() * h.lambda;  // Bᵀλ, free dofs
  const double force_scale = contact_force.cwiseAbs().maxCoeff();
  ASSERT_GT(force_scale, 0.0);
  double equilibrium = 0.0, kinematics = 0.0;
  for (int k = 0; k < s.problem.numSteps(); ++k) {
    // Full, unconstrained K on the full field (prescribed dofs included): free rows = Bᵀλ (eq. 1).
    const Eigen::VectorXd Ku = s.problem.stiffness * s.problem.fullDisplacement(u.col(k), k);
    for (int f = 0; f < s.problem.numFreeDofs(); ++f)
      equilibrium = std::max(equilibrium, std::abs(Ku[s.problem.free_dofs[f]] - contact_force(f, k)));
    kinematics = std::max(kinematics, (s.problem.contact.B * u.col(k) - h.v.col(k)).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(equilibrium / force_scale, 1e-11);
  EXPECT_LE(kinematics / h.v.cwiseAbs().maxCoeff(), 1e-12);
}

TEST(IncrementalSolver, NoContactBeforeTheBodyTravelsTheInitialGapAndContactAfterwards) {
  for (auto [arc_nodes, steps] : {std::pair{31, 41}, std::pair{101, 201}}) {
    const Solved& s = solvedSeed(arc_nodes, steps);
    const auto& h = s.result.interface;
    const int touch = touchInstant(steps);
    for (int k = 0; k < touch; ++k) EXPECT_EQ(h.lambda.col(k).cwiseAbs().maxCoeff(), 0.0) << "instant " << k;
    // At t = 0.2 the lowest node just touches (gap zero to round-off of g0 = 0.01).
    const Eigen::VectorXd gap = s.problem.contact.initial_gap + h.v.col(touch)(Eigen::seq(0, Eigen::last, 2));
    EXPECT_NEAR(gap.minCoeff(), 0.0, 1e-14);
    for (int k = touch + 1; k < steps; ++k)
      EXPECT_GT(h.lambda.row(2 * (s.problem.contact.size() / 2)).coeff(k), 0.0) << "bottom node open at instant " << k;
  }
}

TEST(IncrementalSolver, TangentialForceIsMuTimesNormalForceWhenEveryClosedNodeSlips) {
  const Solved& s = solvedSeed(101, 201);
  const auto& h = s.result.interface;
  const double mu = s.problem.contact.friction;
  int closed_instants = 0, all_slip = 0;
  for (int k = 0; k < s.problem.numSteps(); ++k) {
    const auto c = states(s, k);
    const auto count = [&](stc::ContactState x) { return std::count(c.begin(), c.end(), x); };
    if (count(stc::ContactState::Open) == static_cast<long>(c.size())) continue;
    ++closed_instants;
    if (count(stc::ContactState::Stick) > 0) continue;
    ++all_slip;
    const double normal = h.lambda.col(k)(Eigen::seq(0, Eigen::last, 2)).sum();
    const double tangential = h.lambda.col(k)(Eigen::seq(1, Eigen::last, 2)).sum();
    // The top edge moves +x, so friction on the body points −x: Σλ_t = −μ Σλ_n.
    EXPECT_NEAR(tangential, -mu * normal, 1e-12 * mu * normal) << "instant " << k;
  }
  std::cout << "[ seed     ] " << all_slip << " of " << closed_instants << " instants with contact slip everywhere\n";
  EXPECT_GE(2 * all_slip, closed_instants) << "docs/method.md §6: the seed slides almost everywhere";
}

// min ½λᵀW_nnλ + λᵀq, λ ≥ 0 (q = v_0,n + g0) by projected Gauss–Seidel from zero, until the natural
// residual ‖min(λ, g / W_ii)‖∞ is below 1e-12 of the force scale.
Eigen::VectorXd projectedGaussSeidel(const Eigen::MatrixXd& Wnn, const Eigen::VectorXd& q) {
  const int n = static_cast<int>(q.size());
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(n);
  const double scale = (q.cwiseAbs().array() / Wnn.diagonal().array()).maxCoeff();
  for (int sweep = 0; sweep < 1000000; ++sweep) {
    for (int i = 0; i < n; ++i) lambda[i] = std::max(0.0, lambda[i] - (Wnn.row(i).dot(lambda) + q[i]) / Wnn(i, i));
    const Eigen::VectorXd g = Wnn * lambda + q;
    const double natural = lambda.cwiseMin(g.cwiseQuotient(Wnn.diagonal())).cwiseAbs().maxCoeff();
    if (natural <= 1e-12 * std::max(scale, lambda.maxCoeff())) return lambda;
  }
  ADD_FAILURE() << "projected Gauss–Seidel did not converge";
  return lambda;
}

TEST(IncrementalSolver, FrictionlessSolutionSolvesTheContactQuadraticProgramAtEveryInstant) {
  stc::Scene scene = seedScene(31, 41);
  scene.contact.friction = 0.0;
  const Solved s = solve(scene);
  ASSERT_TRUE(s.result.summary.converged()) << s.result.summary.message;
  const stc::CholmodFactor factor(s.problem.stiffness_free, "K_ff");
  const auto condensed = stc::CondensedInterface::build(s.problem, factor);
  const auto normal = Eigen::seq(0, Eigen::last, 2);
  const Eigen::MatrixXd Wnn = condensed.delassus(normal, normal);
  const auto& h = s.result.interface;
  const double force_scale = h.lambda.cwiseAbs().maxCoeff();
  ASSERT_GT(force_scale, 0.0);
  for (int k = 0; k < s.problem.numSteps(); ++k) {
    const Eigen::VectorXd q = condensed.free_response.col(k)(normal) + s.problem.contact.initial_gap;
    const Eigen::VectorXd reference = projectedGaussSeidel(Wnn, q);
    const double scale = std::max(reference.maxCoeff(), 1e-3 * force_scale);
    EXPECT_LE((h.lambda.col(k)(normal) - reference).cwiseAbs().maxCoeff(), 1e-8 * scale) << "instant " << k;
    EXPECT_LE(h.lambda.col(k)(Eigen::seq(1, Eigen::last, 2)).cwiseAbs().maxCoeff(), 1e-14 * force_scale);
  }
}

TEST(IncrementalSolver, ConvergesInFewNewtonIterationsPerInstant) {
  for (auto [arc_nodes, steps] : {std::pair{31, 41}, std::pair{101, 201}}) {
    const Solved& s = solvedSeed(arc_nodes, steps);
    const int newton = newtonIterations(s.result.summary);
    ASSERT_GE(newton, 0) << "message lacks the Newton count: " << s.result.summary.message;
    std::cout << "[ seed     ] arc_nodes " << arc_nodes << ", steps " << steps << ": " << s.result.summary.message
              << "\n";
    EXPECT_LE(newton, 20 * steps);  // observed 38 (31, 41) and 229 (101, 201)
    for (const auto& record : s.result.summary.history) EXPECT_LE(record.indicator, 1e-13);
  }
}

TEST(IncrementalSolver, SummaryHasOneRecordPerInstant) {
  const Solved& s = solvedSeed(31, 41);
  const auto& summary = s.result.summary;
  EXPECT_EQ(summary.solver, "incremental");
  EXPECT_EQ(summary.termination, stc::Termination::Converged);
  ASSERT_EQ(static_cast<int>(summary.history.size()), s.problem.numSteps());
  EXPECT_EQ(summary.iterations, s.problem.numSteps());
  // The Delassus columns of the nodes within reach of the prescribed motion, and the load terms.
  const int solves = 2 * static_cast<int>(stc::reachZone(s.problem)->size()) + static_cast<int>(s.problem.loads.size());
  for (std::size_t k = 0; k < summary.history.size(); ++k) {
    const auto& r = summary.history[k];
    EXPECT_EQ(r.iteration, static_cast<int>(k) + 1);
    EXPECT_EQ(r.relaxations, 0);
    EXPECT_EQ(r.sparse_solves, solves);
    EXPECT_FALSE(r.error.has_value());
    if (k > 0) EXPECT_GE(r.wall_s, summary.history[k - 1].wall_s);
  }
  EXPECT_GE(summary.wall_s, summary.history.back().wall_s);
}

TEST(IncrementalSolver, CallbackReturningFalseStopsAfterThatInstant) {
  const stc::Problem problem = stc::buildProblem(seedScene(31, 41));
  const auto result = stc::solveIncremental(problem, {}, {.callback = [](const stc::IterationRecord& r) { return r.iteration < 12; }});
  EXPECT_EQ(result.summary.termination, stc::Termination::StoppedByCallback);
  EXPECT_EQ(result.summary.history.size(), 12u);
  EXPECT_EQ(result.interface.v.rightCols(41 - 12).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_NE(result.summary.message.find("Newton iterations"), std::string::npos);
}

TEST(IncrementalSolver, ReportsNumericalIssueNamingTheInstantWhenNewtonRunsOut) {
  const stc::Problem problem = stc::buildProblem(seedScene(31, 41));
  stc::IncrementalOptions options;
  options.max_newton_iterations = 1;  // the closing instants need 2
  const auto result = stc::solveIncremental(problem, options);
  EXPECT_EQ(result.summary.termination, stc::Termination::NumericalIssue);
  std::smatch match;
  ASSERT_TRUE(std::regex_search(result.summary.message, match, std::regex("instant k = ([0-9]+)")))
      << result.summary.message;
  EXPECT_EQ(static_cast<int>(result.summary.history.size()), std::stoi(match[1]));
  EXPECT_GT(std::stoi(match[1]), touchInstant(41)) << "no Newton step is needed before contact";
  EXPECT_GE(newtonIterations(result.summary), 0);
}

TEST(IncrementalSolver, ReportsNumericalIssueOnNonFiniteData) {
  stc::Problem problem = stc::buildProblem(seedScene(31, 41));
  problem.contact.initial_gap[3] = std::nan("");
  const auto result = stc::solveIncremental(problem);
  EXPECT_EQ(result.summary.termination, stc::Termination::NumericalIssue);
  EXPECT_NE(result.summary.message.find("instant k = 0"), std::string::npos) << result.summary.message;
}

TEST(IncrementalOptions, ValidateNamesTheFieldTheValueAndTheRule) {
  EXPECT_NO_THROW(stc::IncrementalOptions{}.validate());
  const auto message = [](const stc::IncrementalOptions& o) {
    try {
      o.validate();
    } catch (const stc::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  for (double bad : {0.0, -1e-13, 1.0, std::nan(""), HUGE_VAL}) {
    stc::IncrementalOptions o;
    o.tolerance = bad;
    EXPECT_NE(message(o).find("incremental option tolerance = "), std::string::npos) << message(o);
    EXPECT_NE(message(o).find("must be in (0, 1)"), std::string::npos);
  }
  stc::IncrementalOptions o;
  o.max_newton_iterations = 0;
  EXPECT_EQ(message(o), "incremental option max_newton_iterations = 0: must be >= 1");
  const stc::Problem problem = stc::buildProblem(seedScene(31, 41));
  EXPECT_THROW(stc::solveIncremental(problem, o), stc::InputError);
}

TEST(ContactState, ClassifiesWithRelativeTolerances) {
  using stc::ContactState;
  EXPECT_EQ(stc::classifyContact(0.0, 0.0, 0.3, 0.2, 10.0, 1.0), ContactState::Open);
  EXPECT_EQ(stc::classifyContact(1e-10, 0.0, 0.3, 0.2, 10.0, 1.0), ContactState::Open);
  EXPECT_EQ(stc::classifyContact(1.0, 0.1, 0.0, 0.2, 10.0, 1.0), ContactState::Stick);
  EXPECT_EQ(stc::classifyContact(1.0, -0.2, 1e-3, 0.2, 10.0, 1.0), ContactState::Slip);
  EXPECT_EQ(stc::classifyContact(1.0, -0.2 * (1 - 1e-12), 1e-3, 0.2, 10.0, 1.0), ContactState::Slip);
  EXPECT_EQ(stc::classifyContact(1.0, -0.2, 1e-13, 0.2, 10.0, 1.0), ContactState::Stick);  // impending slip
  EXPECT_STREQ(stc::toString(ContactState::Open), "open");
  EXPECT_STREQ(stc::toString(ContactState::Stick), "stick");
  EXPECT_STREQ(stc::toString(ContactState::Slip), "slip");
}

TEST(ContactLawCheck, FlagsEachKindOfViolationInAPerturbedSolution) {
  const Solved& s = solvedSeed(31, 41);
  const int k = 30, i = s.problem.contact.size() / 2;  // a closed, slipping node
  ASSERT_GT(s.result.interface.lambda(2 * i, k), 0.0);
  const auto perturbed = [&](auto change) {
    stc::InterfaceHistory h = s.result.interface;
    change(h);
    return stc::checkContactLaw(s.problem, h);
  };
  // Each perturbation is well above round-off (~1e-15) and shows up, relative, well above 1e-6
  // (the complementarity scale G is the largest gap, ~1 for the far arc nodes; slip increments are
  // small against V, the largest displacement).
  const double visible = 1e-6;
  EXPECT_GT(perturbed([&](auto& h) { h.v(2 * i, k) -= 1e-3; }).penetration, visible);
  EXPECT_GT(perturbed([&](auto& h) { h.lambda(2 * i, k) *= -1.0; }).negative_pressure, visible);
  EXPECT_GT(perturbed([&](auto& h) { h.v(2 * i, k) += 1e-3; }).complementarity, visible);
  EXPECT_GT(perturbed([&](auto& h) { h.lambda(2 * i + 1, k) *= 1.5; }).cone, visible);
  EXPECT_GT(perturbed([&](auto& h) { h.lambda(2 * i + 1, k) *= 0.5; }).stick_slip, visible);
  EXPECT_GT(perturbed([&](auto& h) { h.lambda(2 * i + 1, k) *= -1.0; }).slip_direction, visible);
  EXPECT_LE(stc::checkContactLaw(s.problem, s.result.interface).max(), kLawTolerance);
}

}  // namespace
