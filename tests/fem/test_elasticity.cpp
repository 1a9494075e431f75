// P1 elasticity: symmetry, rigid-body kernel, patch test, observed O(h) energy-norm convergence.
#include <gsl/gsl_fit.h>
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <functional>

#include "stcontact/fem/elasticity.hpp"
#include "stcontact/mesh/half_disc.hpp"

namespace {

using Field = std::function<Eigen::Vector2d(const Eigen::Vector2d&)>;
const stc::MaterialSpec kSteelLike{3000.0, 0.3};

// Solves K u = 0 with u = exact on every boundary node (arc and top): the discrete harmonic extension.
Eigen::VectorXd solveDirichlet(const stc::TriMesh& mesh, const Eigen::SparseMatrix<double>& K, const Field& exact) {
  std::vector<bool> fixed(mesh.numDofs(), false);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.numDofs());
  for (const char* name : {"arc", "top"})
    for (int node : mesh.group(name).nodes) {
      fixed[2 * node] = fixed[2 * node + 1] = true;
      u.segment<2>(2 * node) = exact(mesh.nodes.col(node));
    }
  std::vector<int> index(mesh.numDofs(), -1), free;
  for (int d = 0; d < mesh.numDofs(); ++d)
    if (!fixed[d]) { index[d] = static_cast<int>(free.size()); free.push_back(d); }
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd rhs = -(K * u);
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

Eigen::VectorXd interpolate(const stc::TriMesh& mesh, const Field& f) {
  Eigen::VectorXd u(mesh.numDofs());
  for (int n = 0; n < mesh.numNodes(); ++n) u.segment<2>(2 * n) = f(mesh.nodes.col(n));
  return u;
}

}  // namespace

TEST(Elasticity, StiffnessIsSymmetric) {
  const stc::TriMesh mesh = stc::makeHalfDisc({1.0, 21, 1.135});
  for (auto plane : {stc::PlaneModel::Strain, stc::PlaneModel::Stress}) {
    const Eigen::SparseMatrix<double> K = stc::assembleStiffness(mesh, stc::hookeMatrix(kSteelLike, plane));
    const Eigen::SparseMatrix<double> asym = K - Eigen::SparseMatrix<double>(K.transpose());
    EXPECT_LE(asym.norm(), 1e-13 * K.norm());
  }
}

TEST(Elasticity, RigidBodyModesAreInTheKernel) {
  const stc::TriMesh mesh = stc::makeHalfDisc({1.0, 21, 1.135});
  const Eigen::SparseMatrix<double> K = stc::assembleStiffness(mesh, stc::hookeMatrix(kSteelLike, stc::PlaneModel::Strain));
  const std::vector<Field> modes = {[](const Eigen::Vector2d&) { return Eigen::Vector2d(1.0, 0.0); },
                                    [](const Eigen::Vector2d&) { return Eigen::Vector2d(0.0, 1.0); },
                                    [](const Eigen::Vector2d& x) { return Eigen::Vector2d(-x.y(), x.x()); }};
  for (const auto& mode : modes) {
    const Eigen::VectorXd r = interpolate(mesh, mode);
    // Round-off scale: ‖K‖ ‖r‖ ε, with a factor 100 for the sums over elements.
    EXPECT_LE((K * r).norm(), 100 * 1e-16 * K.norm() * r.norm());
  }
  // And nothing else: a non-rigid field (uniform stretch) has positive energy.
  const Eigen::VectorXd s = interpolate(mesh, [](const Eigen::Vector2d& x) { return Eigen::Vector2d(x.x(), 0.0); });
  EXPECT_GT(s.dot(K * s), 0.0);
}

TEST(Elasticity, PatchTestReproducesLinearFieldsExactly) {
  const stc::TriMesh mesh = stc::makeHalfDisc({1.0, 31, 1.135});
  const Field linear = [](const Eigen::Vector2d& x) {
    return Eigen::Vector2d(0.01 + 0.002 * x.x() - 0.003 * x.y(), -0.02 + 0.004 * x.x() + 0.001 * x.y());
  };
  for (auto plane : {stc::PlaneModel::Strain, stc::PlaneModel::Stress}) {
    const Eigen::SparseMatrix<double> K = stc::assembleStiffness(mesh, stc::hookeMatrix(kSteelLike, plane));
    const Eigen::VectorXd u = solveDirichlet(mesh, K, linear);
    EXPECT_LE((u - interpolate(mesh, linear)).lpNorm<Eigen::Infinity>(), 1e-13);
    // Constant stress: σ_xx = D(0,:)·ε on every element.
    const auto stress = stc::elementStresses(mesh, kSteelLike, plane, u);
    EXPECT_LE((stress.row(0).array() - stress(0, 0)).abs().maxCoeff(), 1e-9 * std::abs(stress(0, 0)) + 1e-12);
  }
}

TEST(Elasticity, EnergyErrorConvergesAtOrderOne) {
  // u = (x² − y², −2xy) is divergence-free and harmonic, hence solves Navier's equations with no body
  // force for any Lamé constants. Its strain ε = [2x, −2x, −4y] (Voigt) is linear, so P1 (constant
  // strain) must converge as O(h) in the energy norm. Quadrature: the edge-midpoint rule, exact for
  // the quadratic integrand (ε − ε_h)ᵀ D (ε − ε_h).
  const Field exact = [](const Eigen::Vector2d& x) { return Eigen::Vector2d(x.x() * x.x() - x.y() * x.y(), -2 * x.x() * x.y()); };
  const Eigen::Matrix3d D = stc::hookeMatrix(kSteelLike, stc::PlaneModel::Strain);
  std::vector<double> log_h, log_e;
  for (int arc_nodes : {15, 31, 63, 127}) {
    const stc::TriMesh mesh = stc::makeHalfDisc({1.0, arc_nodes, 1.0});
    const Eigen::VectorXd u = solveDirichlet(mesh, stc::assembleStiffness(mesh, D), exact);
    double error2 = 0.0;
    for (int e = 0; e < mesh.numElements(); ++e) {
      Eigen::Matrix<double, 6, 1> ue;
      for (int a = 0; a < 3; ++a) ue.segment<2>(2 * a) = u.segment<2>(2 * mesh.triangles(a, e));
      const Eigen::Vector3d eps_h = stc::strainDisplacement(mesh, e) * ue;
      for (int a = 0; a < 3; ++a) {
        const Eigen::Vector2d mid = 0.5 * (mesh.nodes.col(mesh.triangles(a, e)) + mesh.nodes.col(mesh.triangles((a + 1) % 3, e)));
        const Eigen::Vector3d d = Eigen::Vector3d(2 * mid.x(), -2 * mid.x(), -4 * mid.y()) - eps_h;
        error2 += mesh.twiceSignedArea(e) / 6.0 * d.dot(D * d);
      }
    }
    log_h.push_back(std::log(1.0 / (arc_nodes + 1)));
    log_e.push_back(0.5 * std::log(error2));
  }
  double c0, slope, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(log_h.data(), 1, log_e.data(), 1, log_h.size(), &c0, &slope, &cov00, &cov01, &cov11, &sumsq);
  // Theory: slope 1 (P1 energy-norm rate for an H² solution); the window allows the pre-asymptotic
  // effect of the polygonal boundary on the coarsest mesh.
  EXPECT_NEAR(slope, 1.0, 0.1);
}
