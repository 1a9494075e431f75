#pragma once
// The fields of an output frame (docs/interface.md, "solution.h5 and solution.xdmf"), whatever the format they are written
// in (solution.h5 + solution.xdmf, or solution.pvd + vtu/): the displacement, the contact force and
// state on the nodes, the stress tensor and von Mises on the elements, at chosen instants; the
// displacement taken from the one the strategy holds (no factor, no solve) or solved from λ.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "stcontact/io/vtu_arrays.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"

namespace stc {

/// Every `stride`-th instant of `steps`, and the last one.
std::vector<int> frameSteps(int steps, int stride);

/// The stride of output.frame_stride = 0 ("auto"): 1 while every instant's frame fits in
/// kAutoFrameBytes (single precision, before compression), else the smallest stride that keeps the
/// frames within it.
inline constexpr double kAutoFrameBytes = 16.0 * (1 << 20);
int autoFrameStride(const Problem& problem);
/// The stride a run uses: `stride` when set (>= 1), else autoFrameStride.
int frameStride(const Problem& problem, int stride);

/// The fields of one frame: displacement, contact_force and contact_state (−1: not a contact node,
/// 0 open, 1 stick, 2 slip) on the nodes, with `body` when given (1 × n, two bodies); stress (VTK's
/// order xx, yy, zz, xy, yz, xz) and von_mises on the elements.
struct FrameFields {
  std::vector<PointField> nodal;
  std::vector<CellField> cells;
};

/// The absolute displacement (every dof) at output instants: formed from the displacement the
/// strategy holds (SolveResult::displacement) or, when it holds none, solved from λ with K_ff from
/// `operators` (one sparse solve per frame, counted by solves()). Safe to call from several threads,
/// one `thread` index each.
class FrameDisplacement {
 public:
  FrameDisplacement(const Problem& problem, const SolveResult& result, PreparedOperators& operators, int threads);
  Eigen::VectorXd at(int k, int thread);
  /// Whether frames need a sparse solve each (the strategy holds no displacement).
  bool solves() const { return factor_ != nullptr; }

 private:
  const Problem& problem_;
  const SolveResult& result_;
  std::shared_ptr<const SpdSolver> factor_;
  std::vector<SpdSolver::Workspace> workspaces_;
};

/// The stress tensor (rows in VTK's order xx, yy, zz, xy, yz, xz) and von Mises of every element,
/// from the absolute displacement `u` (every dof), each element with its body's material.
std::vector<CellField> elementStressFields(const Problem& problem, const Eigen::VectorXd& u);

/// The fields of instant k from its absolute displacement `u`.
FrameFields frameFields(const Problem& problem, const SolveResult& result, const ContactStateTable& states, int k,
                        const Eigen::VectorXd& u, const Eigen::MatrixXd& bodies = {});

}  // namespace stc
