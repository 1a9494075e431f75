#include "stcontact/io/frame_fields.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "stcontact/core/overloaded.hpp"
#include "stcontact/fem/elasticity.hpp"
#include "stcontact/fem/elasticity_3d.hpp"
#include "stcontact/operators/displacement.hpp"

namespace stc {
namespace {

// Nodal contact force (λ_n n + Σ_a λ_{t,a} τ_a; its opposite, times w_j, on the master nodes j of two
// bodies) and state code (−1: not a contact node, 0 open, 1 stick, 2 slip; a master node shared by
// several pairs shows the highest).
void contactFields(const Problem& problem, const SolveResult& result, const ContactStateTable& states, int k,
                   Eigen::MatrixXd& force, Eigen::MatrixXd& state) {
  const auto& c = problem.contact;
  const int d = c.dimension;
  force = Eigen::MatrixXd::Zero(d, problem.numNodes());
  state = Eigen::MatrixXd::Constant(1, problem.numNodes(), -1.0);
  for (int i = 0; i < c.size(); ++i) {
    const int node = c.nodes[i];
    force.col(node) = inGlobalFrame(c, i, result.interface.lambda.col(k).segment(c.normalRow(i), d));
    state(0, node) = static_cast<double>(states.state(i, k));
    if (!c.isPair()) continue;
    for (Eigen::Index j = 0; j < c.master_facets.rows() && c.master_facets(j, i) >= 0; ++j) {  // action and reaction
      const int master = c.master_facets(j, i);
      const Eigen::VectorXd share = -c.master_weights(j, i) * force.col(node);
      if (state(0, master) < 0.0) force.col(master) = share;  // its first pair (node to node: its only one)
      else force.col(master) += share;
      state(0, master) = std::max(state(0, master), state(0, node));
    }
  }
}

/// The symmetric tensor of `stress` in VTK's order xx, yy, zz, xy, yz, xz (vtu_writer.hpp): row k of
/// the result is row rows[k] of `stress`, or 0 where rows[k] is −1.
Eigen::MatrixXd inVtkOrder(const Eigen::Ref<const Eigen::MatrixXd>& stress, const std::array<int, 6>& rows) {
  Eigen::MatrixXd tensor = Eigen::MatrixXd::Zero(6, stress.cols());
  for (int k = 0; k < 6; ++k)
    if (rows[k] >= 0) tensor.row(k) = stress.row(rows[k]);
  return tensor;
}

}  // namespace

// Two bodies of two materials: both computed, each element's taken.
std::vector<CellField> elementStressFields(const Problem& problem, const Eigen::VectorXd& u) {
  const auto cellFields = [](const Eigen::MatrixXd& stress, const std::array<int, 6>& vtkRows) {
    return std::vector<CellField>{{"stress", inVtkOrder(stress, vtkRows), FieldKind::SymmetricTensor},
                                  {"von_mises", stress.bottomRows(1)}};
  };
  const auto perElement = [&](auto&& stresses) {
    auto out = stresses(problem.material);
    if (!problem.master_material) return out;
    const auto master = stresses(*problem.master_material);
    for (Eigen::Index e = 0; e < out.cols(); ++e)
      if (problem.master_elements[static_cast<std::size_t>(e)]) out.col(e) = master.col(e);
    return out;
  };
  return std::visit(
      Overloaded{[&](const TriMesh& m) {
                   // rows σ_xx, σ_yy, σ_xy, σ_zz, von Mises (σ_zz = ν(σ_xx + σ_yy) in plane strain,
                   // 0 in plane stress); σ_yz = σ_xz = 0
                   return cellFields(perElement([&](const MaterialSpec& mat) { return elementStresses(m, mat, problem.plane, u); }),
                                     {0, 1, 3, 2, -1, -1});
                 },
                 [&](const TetMesh& m) {
                   // rows σ_xx, σ_yy, σ_zz, σ_yz, σ_xz, σ_xy, von Mises
                   return cellFields(perElement([&](const MaterialSpec& mat) { return elementStresses(m, mat, u); }),
                                     {0, 1, 2, 5, 3, 4});
                 }},
      problem.body);
}

namespace {

// Bytes of one frame in single precision: d + d + 1 values per node, 6 + 1 per element.
double frameBytes(const Problem& problem) {
  return 4.0 * ((2.0 * problem.dimension + 1.0) * problem.numNodes() + 7.0 * problem.numElements());
}

}  // namespace

std::vector<int> frameSteps(int steps, int stride) {
  std::vector<int> frames;
  for (int k = 0; k < steps; k += stride) frames.push_back(k);
  if (frames.back() != steps - 1) frames.push_back(steps - 1);
  return frames;
}

int autoFrameStride(const Problem& problem) {
  const int steps = problem.numSteps();
  const int fitting = std::max(1, static_cast<int>(kAutoFrameBytes / frameBytes(problem)));  // frames that fit
  if (fitting >= steps) return 1;
  // frameSteps(steps, s) writes ceil((steps − 1) / s) + 1 frames at most: the smallest s that fits
  const int stride = static_cast<int>(std::ceil(static_cast<double>(steps - 1) / std::max(fitting - 1, 1)));
  return std::clamp(stride, 1, std::max(steps - 1, 1));
}

int frameStride(const Problem& problem, int stride) { return stride >= 1 ? stride : autoFrameStride(problem); }

FrameDisplacement::FrameDisplacement(const Problem& problem, const SolveResult& result, PreparedOperators& operators,
                                     int threads)
    : problem_(problem),
      result_(result),
      factor_(result.displacement.held ? nullptr : operators.stiffnessFree(problem)),
      workspaces_(static_cast<std::size_t>(std::max(threads, 1))) {
  const SeparatedDisplacement& held = result.displacement;
  if (held.held && (held.modes.rows() != problem.numFreeDofs() || held.time.cols() != problem.numSteps()))
    throw std::logic_error("FrameDisplacement: the held displacement is another problem's");
}

Eigen::VectorXd FrameDisplacement::at(int k, int thread) {
  const Eigen::VectorXd free = factor_ ? freeDisplacementAt(problem_, *factor_, result_.interface.lambda.col(k), k,
                                                            workspaces_[static_cast<std::size_t>(thread)])
                                       : result_.displacement.at(k);
  return problem_.absoluteDisplacement(free, k);
}

FrameFields frameFields(const Problem& problem, const SolveResult& result, const ContactStateTable& states, int k,
                        const Eigen::VectorXd& u, const Eigen::MatrixXd& bodies) {
  Eigen::MatrixXd force, state;
  contactFields(problem, result, states, k, force, state);
  const Eigen::MatrixXd displacement = Eigen::Map<const Eigen::MatrixXd>(u.data(), problem.dimension, problem.numNodes());
  std::vector<PointField> nodal{{"displacement", displacement},
                                {"contact_force", std::move(force)},
                                {"contact_state", std::move(state), FieldKind::Code}};
  if (bodies.size() > 0) nodal.push_back({"body", bodies, FieldKind::Code});
  return {std::move(nodal), elementStressFields(problem, u)};
}

}  // namespace stc
