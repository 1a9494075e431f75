// Sizes: divisions = 8 gives (2·8 + 1)²(8 + 1) = 2601 nodes, 7803 dofs, 6·16·16·8 = 12288 tetrahedra
// (tests/mesh/test_half_ball.cpp checks them).
#include "stcontact/mesh/half_ball.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/detail/box_grid.hpp"
#include "stcontact/mesh/detail/cored_box.hpp"

namespace stc {
namespace {

using detail::BoxGrid;

Eigen::Vector3d gradeTowardPole(const Eigen::Vector3d& x, double s, double exponent) {
  const Eigen::Vector3d pole(0.0, 0.0, -1.0);
  if (s == 0.0) return pole;
  return pole + std::pow(s, exponent - 1.0) * (x - pole);
}

// Node positions in the box (before the map onto the ball).
Eigen::Matrix3Xd gradedBoxNodes(const BoxGrid& grid, double grading) {
  Eigen::Matrix3Xd nodes(3, grid.numNodes());
  for (int n = 0; n < grid.numNodes(); ++n)
    nodes.col(n) = gradeTowardPole(grid.reference(n), grid.poleDistance(n), grading);
  return nodes;
}

// Maps the box mesh onto the half ball of the given radius and names its faces: boundary triangles
// on the box's top z = 0 are "top", the others "contact".
TetMesh mapBoxOntoHalfBall(TetMesh box, double radius) {
  std::vector<char> top(box.numNodes());
  for (int n = 0; n < box.numNodes(); ++n) {
    top[n] = box.nodes(2, n) == 0.0;
    box.nodes.col(n) = radius * detail::boxToBall(box.nodes.col(n));
  }
  for (const auto& triangle : boundaryTriangles(box)) {
    const bool onTop = std::all_of(triangle.begin(), triangle.end(), [&](int n) { return top[n] != 0; });
    box.groups[onTop ? "top" : "contact"].triangles.push_back(triangle);
  }
  box.finalizeGroups();
  box.validate();
  return box;
}

}  // namespace

void HalfBallOptions::validate() const {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InputError("half_ball: radius = " + std::to_string(radius) + " must be > 0");
  if (divisions < 2) throw InputError("half_ball: divisions = " + std::to_string(divisions) + " must be >= 2");
  if (!(grading >= 1.0) || !(grading <= 2.0))
    throw InputError("half_ball: grading = " + std::to_string(grading) + " must be in [1, 2]");
  const double nodes = halfBallNodeCount(*this);
  if (nodes * 3 > std::numeric_limits<int>::max())
    throw InputError("half_ball: divisions = " + std::to_string(divisions) + " would make " + std::to_string(nodes) +
                     " nodes, more than the dof numbering holds");
  if (!(core == 0.0 || (core > 0.0 && core < 1.0)))
    throw InputError("half_ball: core = " + std::to_string(core) + " must be 0 (no core) or in (0, 1)");
  // The core lies inside the hole of the outer grid, ‖x − P‖_∞ < d / (2d + 1) (src/mesh/detail/cored_box.hpp).
  if (core >= double(divisions) / (2 * divisions + 1))
    throw InputError("half_ball: core = " + std::to_string(core) + " must be below divisions / (2 divisions + 1) = " +
                     std::to_string(double(divisions) / (2 * divisions + 1)));
}

double halfBallNodeCount(const HalfBallOptions& options) {
  const double d = options.divisions;
  if (options.core <= 0.0) return (2 * d + 1) * (2 * d + 1) * (d + 1);
  const double outer = 2 * d + 1;  // the outer grid's divisions (src/mesh/detail/cored_box.hpp)
  return 3.0 * (2 * outer + 1) * (2 * outer + 1) * (outer + 1);
}

TetMesh makeHalfBall(const HalfBallOptions& options) {
  options.validate();
  if (options.core > 0.0) return mapBoxOntoHalfBall(detail::coredBox(options.divisions, options.core), options.radius);
  const BoxGrid grid(options.divisions);
  TetMesh box;
  box.nodes = gradedBoxNodes(grid, options.grading);
  box.tets = detail::boxTetrahedra(grid);
  return mapBoxOntoHalfBall(std::move(box), options.radius);
}

}  // namespace stc
