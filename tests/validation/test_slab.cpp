// The same physics through both code paths: the seed half-disc extruded along z with u_z = 0 on
// both faces (tests/fixtures/slab_scene.hpp) is in plane strain, so its reactions per unit thickness
// are the 2D seed scene's. They cannot be equal to round-off: the P1 tetrahedra of a prism do not
// span the same fields as its triangle × z, and the contact nodes inside the slab may move along z.
// The goal is agreement within the mesh error of the 2D solution, estimated as the change of its
// reactions when the arc's node spacing is halved (arc_nodes n → 2n + 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fixtures/slab_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/scene/scene.hpp"
#include "validation/validation_support.hpp"

namespace stc::validation {
namespace {

struct Histories {
  std::vector<Resultant> reactions;  // per instant, per unit thickness in 3D
  double scale = 0.0;                // max |P|
};

// Σ λ_n and Σ λ_t1 per instant; in 3D over the slab's contact nodes, divided by its thickness.
Histories reactions(const Scene& scene) {
  const Problem problem = buildProblem(scene);
  const SolveResult r = solveIncremental(problem);
  EXPECT_TRUE(r.summary.converged()) << r.summary.message;
  const int d = problem.contact.dimension;
  const double thickness = d == 3 ? scene.mesh.thickness : 1.0;
  Histories h;
  for (int k = 0; k < problem.numSteps(); ++k) {
    Resultant sum;
    for (int i = 0; i < problem.contact.size(); ++i) {
      sum.normal += r.interface.lambda(d * i, k) / thickness;
      sum.tangential += r.interface.lambda(d * i + 1, k) / thickness;
    }
    h.reactions.push_back(sum);
    h.scale = std::max(h.scale, std::abs(sum.normal));
  }
  if (d == 3)
    for (int row : problem.contact.held_rows)
      EXPECT_EQ(r.interface.lambda.row(row).cwiseAbs().maxCoeff(), 0.0) << "the support takes a held row's force";
  return h;
}

// Largest difference over the instants, relative to max |P| of `b`: normal and tangential.
std::pair<double, double> difference(const Histories& a, const Histories& b) {
  double normal = 0.0, tangential = 0.0;
  for (std::size_t k = 0; k < a.reactions.size(); ++k) {
    normal = std::max(normal, std::abs(a.reactions[k].normal - b.reactions[k].normal) / b.scale);
    tangential = std::max(tangential, std::abs(a.reactions[k].tangential - b.reactions[k].tangential) / b.scale);
  }
  return {normal, tangential};
}

void expectSlabWithinMeshError(int arc_nodes, int steps, double thickness, int layers) {
  const Histories plane = reactions(test::seedScene(arc_nodes, steps));
  const Histories finer = reactions(test::seedScene(2 * arc_nodes + 1, steps));
  const Histories slab = reactions(test::slabScene(arc_nodes, steps, thickness, layers));
  const auto [mesh_n, mesh_t] = difference(finer, plane);
  const auto [slab_n, slab_t] = difference(slab, plane);
  std::printf("[ measured ] arc_nodes %d, steps %d, thickness %g, layers %d: slab against 2D, normal %.2e, "
              "tangential %.2e; 2D mesh error, normal %.2e, tangential %.2e (of max P)\n",
              arc_nodes, steps, thickness, layers, slab_n, slab_t, mesh_n, mesh_t);
  EXPECT_LE(slab_n, mesh_n);
  EXPECT_LE(slab_t, mesh_t);
}

}  // namespace

// Small: arc_nodes 31, 41 instants, 2 layers over 0.05 (93 contact nodes, 62 held rows). Measured:
// slab against 2D 4.2e-4 (normal) and 6.3e-5 (tangential) of max P, 20 times under the 2D mesh
// error (8.5e-3, 1.3e-3).
TEST(Slab, ReactionsPerUnitThicknessAreTheTwoDimensionalOnesWithinMeshError) {
  expectSlabWithinMeshError(31, 41, 0.05, 2);
}

// Full size (docs/validation_3d.md): the seed scene's arc_nodes 101 and 201 instants, the slab
// with 1, 2 and 4 layers (1.5 s in all). Measured: 2.6e-4, 1.9e-4, 1.4e-4 (normal) against a 2D
// mesh error of 1.8e-3.
TEST(Slab, SeedSceneAtFullSize) {
  for (const auto& [thickness, layers] : {std::pair{0.03, 1}, std::pair{0.05, 2}, std::pair{0.1, 4}})
    expectSlabWithinMeshError(101, 201, thickness, layers);
}

}  // namespace stc::validation
