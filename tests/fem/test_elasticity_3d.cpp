// P1 tetrahedron elasticity: Hooke's matrix, symmetry, rigid-body kernel, patch test, energy of a
// uniform uniaxial stress.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <cstdio>
#include <functional>
#include <vector>

#include "stcontact/fem/elasticity_3d.hpp"
#include "stcontact/mesh/half_ball.hpp"

namespace {

using Field = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;
const stc::MaterialSpec kSteelLike{3000.0, 0.3};

stc::TetMesh testBody() { return stc::makeHalfBall({1.2, 4, 1.5}); }

Eigen::VectorXd interpolate(const stc::TetMesh& mesh, const Field& field) {
  Eigen::VectorXd u(mesh.numDofs());
  for (int n = 0; n < mesh.numNodes(); ++n) u.segment<3>(3 * n) = field(mesh.nodes.col(n));
  return u;
}

// Solves K u = 0 with u = exact on every boundary node (top and contact): the discrete extension.
Eigen::VectorXd solveDirichlet(const stc::TetMesh& mesh, const Eigen::SparseMatrix<double>& K, const Field& exact) {
  std::vector<bool> fixed(mesh.numDofs(), false);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.numDofs());
  for (const char* name : {"top", "contact"})
    for (int node : mesh.group(name).nodes) {
      fixed[3 * node] = fixed[3 * node + 1] = fixed[3 * node + 2] = true;
      u.segment<3>(3 * node) = exact(mesh.nodes.col(node));
    }
  std::vector<int> index(mesh.numDofs(), -1), free;
  for (int d = 0; d < mesh.numDofs(); ++d)
    if (!fixed[d]) {
      index[d] = static_cast<int>(free.size());
      free.push_back(d);
    }
  std::vector<Eigen::Triplet<double>> t;
  const Eigen::VectorXd rhs = -(K * u);
  for (int c = 0; c < K.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it)
      if (index[it.row()] >= 0 && index[it.col()] >= 0) t.emplace_back(index[it.row()], index[it.col()], it.value());
  Eigen::SparseMatrix<double> Kff(free.size(), free.size());
  Kff.setFromTriplets(t.begin(), t.end());
  Eigen::VectorXd b(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) b[i] = rhs[free[i]];
  const Eigen::VectorXd x = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(Kff).solve(b);
  for (std::size_t i = 0; i < free.size(); ++i) u[free[i]] = x[i];
  return u;
}

}  // namespace

TEST(Elasticity3d, HookeMatrixIsLameForm) {
  // D = λ 1⊗1 + 2μ I on the normal block, μ on the engineering shears, with
  // λ = Eν/((1+ν)(1−2ν)) and μ = E/(2(1+ν)).
  const double E = kSteelLike.young, nu = kSteelLike.poisson;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> expected = Eigen::Matrix<double, 6, 6>::Zero();
  expected.topLeftCorner<3, 3>().setConstant(lambda);
  expected.topLeftCorner<3, 3>().diagonal().array() += 2 * mu;
  expected.bottomRightCorner<3, 3>().diagonal().setConstant(mu);
  EXPECT_LE((stc::hookeMatrix3d(kSteelLike) - expected).norm(), 1e-12 * expected.norm());
}

TEST(Elasticity3d, StiffnessIsSymmetric) {
  const stc::TetMesh mesh = testBody();
  const Eigen::SparseMatrix<double> K = stc::assembleStiffness(mesh, stc::hookeMatrix3d(kSteelLike));
  EXPECT_EQ(K.rows(), mesh.numDofs());
  const Eigen::SparseMatrix<double> Kt = K.transpose();
  EXPECT_LE((K - Kt).norm(), 1e-14 * K.norm());
}

// The element matrices summed by Eigen's triplets, independently: the node-graph assembly stores the
// same entries and sums each in the same (element) order, so the same bits.
TEST(Elasticity3d, StiffnessEqualsTheTripletSumBitForBit) {
  const stc::TetMesh mesh = testBody();
  const Eigen::Matrix<double, 6, 6> D = stc::hookeMatrix3d(kSteelLike);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Matrix<double, 6, 12> B = stc::strainDisplacement(mesh, e);
    const Eigen::Matrix<double, 12, 12> Ke = mesh.sixSignedVolume(e) / 6.0 * B.transpose() * D * B;
    for (int a = 0; a < 12; ++a)
      for (int b = 0; b < 12; ++b)
        triplets.emplace_back(3 * mesh.tets(a / 3, e) + a % 3, 3 * mesh.tets(b / 3, e) + b % 3, Ke(a, b));
  }
  Eigen::SparseMatrix<double> expected(mesh.numDofs(), mesh.numDofs());
  expected.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> K = stc::assembleStiffness(mesh, D);
  ASSERT_EQ(K.nonZeros(), expected.nonZeros());
  ASSERT_TRUE(K.isCompressed());
  for (int c = 0; c < K.outerSize(); ++c) {
    Eigen::SparseMatrix<double>::InnerIterator it(K, c), ref(expected, c);
    for (; it && ref; ++it, ++ref) {
      ASSERT_EQ(it.row(), ref.row()) << "column " << c;
      ASSERT_EQ(it.value(), ref.value()) << "entry (" << it.row() << ", " << c << ")";
    }
    ASSERT_FALSE(it || ref) << "column " << c;
  }
}

TEST(Elasticity3d, RigidBodyModesAreInTheKernel) {
  const stc::TetMesh mesh = testBody();
  const Eigen::SparseMatrix<double> K = stc::assembleStiffness(mesh, stc::hookeMatrix3d(kSteelLike));
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
    const Eigen::VectorXd translation = interpolate(mesh, [&](const Eigen::Vector3d&) { return e; });
    const Eigen::VectorXd rotation = interpolate(mesh, [&](const Eigen::Vector3d& x) { return e.cross(x); });
    const double t = (K * translation).norm() / (K.norm() * translation.norm());
    const double r = (K * rotation).norm() / (K.norm() * rotation.norm());
    std::printf("axis %d: |K r| / (|K| |r|) = %.1e (translation), %.1e (rotation)\n", axis, t, r);
    EXPECT_LE(t, 1e-10) << "translation " << axis;
    EXPECT_LE(r, 1e-10) << "rotation " << axis;
  }
}

TEST(Elasticity3d, PatchTestReproducesAffineFields) {
  const stc::TetMesh mesh = testBody();
  const Eigen::SparseMatrix<double> K = stc::assembleStiffness(mesh, stc::hookeMatrix3d(kSteelLike));
  Eigen::Matrix3d A;
  A << 0.3, -0.2, 0.1, 0.05, -0.4, 0.25, -0.15, 0.2, 0.35;
  const Eigen::Vector3d b(0.01, -0.02, 0.03);
  const Field affine = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return A * x + b; };
  const Eigen::VectorXd exact = interpolate(mesh, affine);
  const Eigen::VectorXd u = solveDirichlet(mesh, K, affine);
  const double error = (u - exact).lpNorm<Eigen::Infinity>() / exact.lpNorm<Eigen::Infinity>();
  std::printf("patch test: relative max error %.2e\n", error);
  EXPECT_LE(error, 1e-12);
  // And the element strain is the symmetric part of A, in Voigt order with engineering shears.
  const Eigen::Matrix3d eps = 0.5 * (A + A.transpose());
  Eigen::Matrix<double, 6, 1> voigt;
  voigt << eps(0, 0), eps(1, 1), eps(2, 2), 2 * eps(1, 2), 2 * eps(0, 2), 2 * eps(0, 1);
  for (int e = 0; e < mesh.numElements(); ++e) {
    Eigen::Matrix<double, 12, 1> ue;
    for (int a = 0; a < 4; ++a) ue.segment<3>(3 * a) = exact.segment<3>(3 * mesh.tets(a, e));
    ASSERT_LE((stc::strainDisplacement(mesh, e) * ue - voigt).norm(), 1e-12) << "element " << e;
  }
}

TEST(Elasticity3d, UniaxialStressEnergyIsAnalytic) {
  // u = ε₀ (x, −ν y, −ν z) is the uniform uniaxial stress σ = E ε₀ e_x ⊗ e_x, whose energy is
  // ½ σ : ε V = ½ E ε₀² V.
  const stc::TetMesh mesh = testBody();
  const Eigen::SparseMatrix<double> K = stc::assembleStiffness(mesh, stc::hookeMatrix3d(kSteelLike));
  const double strain = 1e-3, nu = kSteelLike.poisson;
  const Field stretch = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return strain * Eigen::Vector3d(x.x(), -nu * x.y(), -nu * x.z());
  };
  const Eigen::VectorXd u = interpolate(mesh, stretch);
  double volume = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) volume += mesh.sixSignedVolume(e) / 6.0;
  const double analytic = 0.5 * kSteelLike.young * strain * strain * volume;
  std::printf("uniaxial stress: relative energy error %.2e\n", (0.5 * u.dot(K * u) - analytic) / analytic);
  EXPECT_NEAR(0.5 * u.dot(K * u), analytic, 1e-12 * analytic);
}
