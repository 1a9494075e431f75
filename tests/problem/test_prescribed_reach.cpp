// The prescribed translation, the contact nodes within its reach and its rigid interface history
// (src/problem/prescribed_reach.hpp), against the motion read from the problem itself: the
// displacement of a driven node, w(t_k).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fixtures/seed_scene.hpp"
#include "fixtures/two_bodies_scene.hpp"
#include "stcontact/problem/prescribed_reach.hpp"
#include "stcontact/problem/problem.hpp"

namespace {

// The nodes with g0_i + min_k n_i · w(t_k) ≤ 0, w(t_k) the prescribed displacement of the first
// node of the top edge (every node of a driven edge moves the same way).
std::vector<int> reachedByTheTopsMotion(const stc::Problem& p) {
  const int top = std::get<stc::TriMesh>(p.body).group("top").nodes.front();
  std::vector<int> nodes;
  for (int i = 0; i < p.contact.size(); ++i) {
    double closest = p.contact.initial_gap[i];
    for (int k = 0; k < p.numSteps(); ++k) {
      const Eigen::VectorXd u = p.fullDisplacement(Eigen::VectorXd::Zero(p.numFreeDofs()), k);
      closest = std::min(closest, p.contact.initial_gap[i] + p.contact.normals.col(i).dot(u.segment<2>(2 * top)));
    }
    if (closest <= 0.0) nodes.push_back(i);
  }
  return nodes;
}

}  // namespace

TEST(PrescribedReach, KeepsTheNodesWhoseGapTheDrivenMotionCloses) {
  const stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 21));
  const auto W = stc::prescribedTranslation(p);
  ASSERT_TRUE(W.has_value());
  const std::vector<int> nodes = stc::nodesWithinReach(p.contact, *W, 0.0);
  EXPECT_EQ(nodes, reachedByTheTopsMotion(p));
  // The seed's top goes 0.11 down: some of the arc, not all of it.
  EXPECT_GT(nodes.size(), 2u);
  EXPECT_LT(nodes.size(), static_cast<size_t>(p.contact.size() / 2));
  // A margin keeps the nodes that far short of the obstacle too.
  EXPECT_GT(stc::nodesWithinReach(p.contact, *W, 0.05).size(), nodes.size());
}

// With obstacle normals off the vertical, both components of the motion count.
TEST(PrescribedReach, ProjectsBothComponentsOfTheMotionOnEachNormal) {
  stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 21));
  for (int i = 0; i < p.contact.size(); ++i) p.contact.normals.col(i) = Eigen::Vector2d(-std::sin(0.4), std::cos(0.4));
  const auto W = stc::prescribedTranslation(p);
  ASSERT_TRUE(W.has_value());
  const std::vector<int> nodes = stc::nodesWithinReach(p.contact, *W, 0.0);
  EXPECT_EQ(nodes, reachedByTheTopsMotion(p));
  EXPECT_FALSE(nodes.empty());
}

TEST(PrescribedReach, HasNoAnswerForAnAppliedForce) {
  stc::Scene scene = stc::test::seedScene(31, 21);
  scene.loads.push_back({"arc", stc::Component::Y, {{0.0, 1.0}, {0.0, -5.0}}});
  EXPECT_FALSE(stc::prescribedTranslation(stc::buildProblem(scene)).has_value());
  // A force that is zero at every instant moves nothing.
  scene.loads.back().history = {{0.0, 1.0}, {0.0, 0.0}};
  EXPECT_TRUE(stc::prescribedTranslation(stc::buildProblem(scene)).has_value());
}

TEST(PrescribedReach, HasNoAnswerForAHistoryAlongTwoAxes) {
  stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 21));
  stc::SeparatedLoad& load = p.loads.front();
  Eigen::Index first = 0;
  load.prescribed.maxCoeff(&first);
  load.prescribed[first % 2 == 0 ? first + 1 : first - 1] = 1.0;  // the same node's other axis
  EXPECT_FALSE(stc::prescribedTranslation(p).has_value());
}

// The rigid start is the interface displacement of the whole body translated by w(t_k): B applied to
// that translation's free dofs, with w read from a driven node.
TEST(PrescribedReach, TheRigidMotionHistoryIsTheTranslatedBodysInterfaceDisplacement) {
  const stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 21));
  const auto W = stc::prescribedTranslation(p);
  ASSERT_TRUE(W.has_value());
  const stc::InterfaceHistory h = stc::rigidMotionHistory(p.contact, *W);
  const int top = std::get<stc::TriMesh>(p.body).group("top").nodes.front();
  for (int k = 0; k < p.numSteps(); ++k) {
    const Eigen::Vector2d w = p.fullDisplacement(Eigen::VectorXd::Zero(p.numFreeDofs()), k).segment<2>(2 * top);
    EXPECT_LT((W->col(k) - w).norm(), 1e-15) << "instant " << k;
    Eigen::VectorXd u_free(p.numFreeDofs());
    for (int i = 0; i < p.numFreeDofs(); ++i) u_free[i] = w[p.free_dofs[i] % 2];
    EXPECT_LT((h.v.col(k) - p.contact.B * u_free).cwiseAbs().maxCoeff(), 1e-14) << "instant " << k;
  }
  EXPECT_EQ(h.lambda.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(h.v.cwiseAbs().maxCoeff(), 0.1);  // the seed's top goes 0.11 down
}

// A zone's rows alone, in any order, are the whole history's rows to the bit (what the reduced
// interface's rounds read in place of the whole history), held rows included.
TEST(PrescribedReach, TheRigidMotionOnSomeRowsIsThoseRowsOfTheWholeHistory) {
  stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 21));
  p.contact.held_rows = {p.contact.normalRow(3) + 1};  // a tangential row held: zero in both
  const auto W = stc::prescribedTranslation(p);
  ASSERT_TRUE(W.has_value());
  const stc::InterfaceHistory whole = stc::rigidMotionHistory(p.contact, *W);
  const std::vector<int> rows = {p.contact.normalRow(3) + 1, 40, 7, 0, p.contact.rows() - 1};
  const stc::InterfaceHistory part = stc::rigidMotionHistory(p.contact, *W, rows);
  ASSERT_EQ(part.v.rows(), static_cast<Eigen::Index>(rows.size()));
  ASSERT_EQ(part.v.cols(), whole.v.cols());
  for (size_t r = 0; r < rows.size(); ++r) {
    EXPECT_TRUE((part.v.row(r).array() == whole.v.row(rows[r]).array()).all()) << "row " << rows[r];
    EXPECT_EQ(part.lambda.row(r).cwiseAbs().maxCoeff(), 0.0);
  }
  EXPECT_EQ(part.v.row(0).cwiseAbs().maxCoeff(), 0.0);  // the held row
  EXPECT_GT(part.v.cwiseAbs().maxCoeff(), 0.1);
}

// Two bodies: the gaps close by the relative motion, w = the slave body's translation minus the
// master body's, whichever body is driven: the upper half-disc driven as the slave (w = its top's
// motion), then as the master (w = minus it, the lower body's normal pointing down).
TEST(PrescribedReach, TwoBodiesTakeTheSlavesTranslationMinusTheMasters) {
  stc::Scene scene = stc::test::mirroredPair(stc::test::seedScene(21, 11));
  const stc::Problem upper_slave = stc::buildProblem(scene);
  const auto w = stc::prescribedTranslation(upper_slave);
  ASSERT_TRUE(w.has_value());
  const int top = std::get<stc::TriMesh>(upper_slave.body).group("top").nodes.front();
  for (int k = 0; k < upper_slave.numSteps(); ++k) {
    const Eigen::VectorXd u = upper_slave.fullDisplacement(Eigen::VectorXd::Zero(upper_slave.numFreeDofs()), k);
    EXPECT_EQ(w->col(k), Eigen::Vector2d(u.segment<2>(2 * top))) << k;
  }
  std::swap(scene.contact.boundary, scene.contact.master);
  scene.contact.normal = Eigen::Vector2d(0.0, -1.0);
  const stc::Problem upper_master = stc::buildProblem(scene);
  const auto w_master = stc::prescribedTranslation(upper_master);
  ASSERT_TRUE(w_master.has_value());
  EXPECT_EQ(*w_master, -*w);
  EXPECT_EQ(stc::nodesWithinReach(upper_master.contact, *w_master, 0.0),
            stc::nodesWithinReach(upper_slave.contact, *w, 0.0));
  EXPECT_FALSE(stc::nodesWithinReach(upper_slave.contact, *w, 0.0).empty());
}
