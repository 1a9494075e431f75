#include "stcontact/io/run_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "stcontact/core/clock.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/core/overloaded.hpp"
#include "stcontact/core/threads.hpp"
#include "stcontact/fem/elasticity.hpp"
#include "stcontact/fem/elasticity_3d.hpp"
#include "stcontact/io/atomic_file.hpp"
#include "stcontact/io/body_blocks.hpp"
#include "stcontact/io/contact_tables.hpp"
#include "stcontact/io/json_writer.hpp"
#include "stcontact/io/vtu_writer.hpp"
#include "stcontact/linalg/ranks.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/mesh/connected_parts.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"

namespace stc {
namespace {

std::vector<int> frameSteps(int steps, int stride) {
  std::vector<int> frames;
  for (int k = 0; k < steps; k += stride) frames.push_back(k);
  if (frames.back() != steps - 1) frames.push_back(steps - 1);
  return frames;
}

// vtu/step_NNNNN.vtu, or vtu/step_NNNNN_body<b>.vtu for body b of several.
std::string frameName(int k, int body = -1) {
  char name[48];
  if (body < 0) std::snprintf(name, sizeof name, "vtu/step_%05d.vtu", k);
  else std::snprintf(name, sizeof name, "vtu/step_%05d_body%d.vtu", k, body);
  return name;
}

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

VtuGrid gridOf(const Problem& problem, VtuPrecision precision) {
  return std::visit([precision](const auto& mesh) { return VtuGrid(mesh, precision); }, problem.body);
}

// How a frame is written: one grid (one body: the frames as they always were), or, when the mesh
// holds two bodies in contact (docs/two_bodies.md), one block per body (io/body_blocks.hpp) and the
// body of each node (1 × n: 0, 1, ...) as a field.
struct FrameLayout {
  std::optional<VtuGrid> grid;
  std::vector<BodyBlock> blocks;
  Eigen::MatrixXd bodies;  ///< empty for one body

  int parts() const { return grid ? 1 : static_cast<int>(blocks.size()); }
  /// Part b of instant k in the collection: vtu/step_NNNNN.vtu, or vtu/step_NNNNN_body<b>.vtu named "body b".
  PvdDataSet dataSet(const Problem& problem, int k, int b) const {
    if (grid) return {problem.times[k], frameName(k), 0, ""};
    return {problem.times[k], frameName(k, b), b, "body " + std::to_string(b)};
  }
};

FrameLayout frameLayout(const Problem& problem, VtuPrecision precision) {
  if (!problem.contact.isPair()) return {gridOf(problem, precision), {}, {}};
  const std::vector<int> part = partOfNodes(problem.body);
  Eigen::MatrixXd codes(1, static_cast<Eigen::Index>(part.size()));
  for (std::size_t i = 0; i < part.size(); ++i) codes(0, static_cast<Eigen::Index>(i)) = part[i];
  return {std::nullopt, bodyBlocks(problem.body, part, precision), std::move(codes)};
}

// The fields of a frame: displacement, contact force and state (and the body, when two) on the
// nodes; the stress tensor and von Mises on the elements.
struct FrameFields {
  std::vector<PointField> nodal;
  std::vector<CellField> cells;
};

FrameFields frameFields(const Problem& problem, const Eigen::VectorXd& u, const Eigen::MatrixXd& force,
                        const Eigen::MatrixXd& state, const Eigen::MatrixXd& bodies) {
  const Eigen::MatrixXd displacement = Eigen::Map<const Eigen::MatrixXd>(u.data(), problem.dimension, problem.numNodes());
  std::vector<PointField> nodal{{"displacement", displacement},
                                {"contact_force", force},
                                {"contact_state", state, FieldKind::Code}};
  if (bodies.size() > 0) nodal.push_back({"body", bodies, FieldKind::Code});
  const auto cellFields = [](const Eigen::MatrixXd& stress, const std::array<int, 6>& vtkRows) {
    return std::vector<CellField>{{"stress", inVtkOrder(stress, vtkRows), FieldKind::SymmetricTensor},
                                  {"von_mises", stress.bottomRows(1)}};
  };
  // Each element's stresses with its body's material (two bodies of two materials: both computed,
  // each element's taken).
  const auto perElement = [&](auto&& stresses) {
    auto out = stresses(problem.material);
    if (!problem.master_material) return out;
    const auto master = stresses(*problem.master_material);
    for (Eigen::Index e = 0; e < out.cols(); ++e)
      if (problem.master_elements[static_cast<std::size_t>(e)]) out.col(e) = master.col(e);
    return out;
  };
  const std::vector<CellField> cells = std::visit(
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
  return {std::move(nodal), cells};
}

}  // namespace

std::string historyCsv(const SolveSummary& summary) {
  std::ostringstream out;
  out.precision(12);
  out << "iteration,relaxations,indicator,error,rank,wall_s,error_estimate,sparse_solves,krylov_iterations\n";
  for (const auto& r : summary.history) {
    out << r.iteration << ',' << r.relaxations << ',' << r.indicator << ',';
    if (r.error) out << *r.error;
    out << ',' << r.rank << ',' << r.wall_s << ',';
    if (std::isfinite(r.error_estimate)) out << r.error_estimate;
    out << ',' << r.sparse_solves << ',' << r.krylov_iterations << '\n';
  }
  return out.str();
}

namespace {

// The solve on a sub-grid of instants that nested iteration started from (docs/method.md §5), its
// counts and time included in the solve's; null when there was none.
std::optional<JsonObject> subGridJson(const SolveSummary& summary) {
  for (const SolveStage& stage : summary.stages)
    if (stage.kind == SolveStage::Kind::SubGrid)
      return JsonObject()
          .add("relaxations", stage.relaxations)
          .add("sparse_solves", stage.sparse_solves)
          .add("wall_s", stage.wall_s);
  return std::nullopt;
}

}  // namespace

namespace {

// summary.json's "preparations": each operator the run prepared (src/operators/prepared_operators.hpp).
std::vector<JsonObject> preparationsJson(const std::vector<Preparation>& preparations) {
  std::vector<JsonObject> out;
  for (const Preparation& p : preparations) {
    JsonObject entry;
    entry.add("operator", p.name).add("backend", p.backend).add("rows", p.rows);
    if (p.contact_nodes > 0) entry.add("contact_nodes", p.contact_nodes);
    entry.add("factor_nonzeros", p.factor_nonzeros).add("seconds", p.seconds).add("uses", p.uses);
    if (p.iterative)
      entry.add("krylov_solves", p.krylov.solves)
          .add("krylov_iterations", p.krylov.iterations)
          .add("krylov_max_iterations", p.krylov.max_iterations);
    out.push_back(std::move(entry));
  }
  return out;
}

}  // namespace

std::string summaryJson(const Problem& problem, const SolveSummary& summary, const RunInfo& info,
                        const std::vector<Preparation>& preparations, const WriterCounts& writer) {
  // The writing rank's peak includes the writing so far.
  std::vector<double> peaks = info.peak_memory_bytes.empty() ? std::vector<double>{0.0} : info.peak_memory_bytes;
  double& own = peaks[static_cast<std::size_t>(std::min<int>(currentRanks().rank, static_cast<int>(peaks.size()) - 1))];
  own = std::max(own, peakResidentBytes());
  JsonObject json;
  json.add("solver", summary.solver)
      .add("termination", toString(summary.termination))
      .add("message", summary.message)
      .add("iterations", summary.iterations)
      .add("relaxations", summary.relaxations)
      .add("sparse_solves", summary.sparseSolves())
      .add("krylov_iterations", summary.krylov_iterations)
      .add("writer_sparse_solves", writer.sparse_solves)
      .add("indicator", summary.indicator)
      .add("error", summary.error)
      .add("error_estimate", std::isfinite(summary.error_estimate) ? std::optional<double>(summary.error_estimate)
                                                                   : std::nullopt)
      .add("wall_s", summary.wall_s)
      .add("reference_s", info.reference_s)
      .add("write_s", writer.seconds)
      .add("run_s", info.started ? std::optional<double>(secondsSince(*info.started)) : std::nullopt)
      .add("sub_grid", subGridJson(summary))
      .add("threads", threadCount())
      .add("ranks", currentRanks().size)
      .add("peak_memory_bytes", *std::max_element(peaks.begin(), peaks.end()))
      .add("peak_memory_bytes_per_rank", peaks)
      .add("blas_kernels", linalg::blasKernels())
      .add("n_dofs", problem.numDofs())
      .add("n_contact_nodes", problem.contact.size())
      .add("n_steps", problem.numSteps())
      .add("preparations", preparationsJson(preparations))
      .add("version", info.version)
      .add("parameters", RawJson{info.parameters_json});
  return json.str() + "\n";
}

long writeSolutionSeries(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                         int stride, VtuPrecision precision, PreparedOperators& operators) {
  ensureWritableDirectory(dir / "vtu");
  const SeparatedDisplacement& held = result.displacement;
  if (held.held && (held.modes.rows() != problem.numFreeDofs() || held.time.cols() != problem.numSteps()))
    throw std::logic_error("writeSolutionSeries: the held displacement is another problem's");
  const std::shared_ptr<const SpdSolver> factor = held.held ? nullptr : operators.stiffnessFree(problem);
  const ContactStateTable states(problem.contact, result.admissible());
  const FrameLayout layout = frameLayout(problem, precision);
  const std::vector<int> steps = frameSteps(problem.numSteps(), stride);
  // The frames are independent: each thread solves with its own workspace and writes its own files.
  const int threads = threadCount();
  std::vector<SpdSolver::Workspace> workspaces(static_cast<std::size_t>(threads));
  parallelFor(static_cast<int>(steps.size()), threads, [&](int item, int thread) {
    const int k = steps[static_cast<std::size_t>(item)];
    const Eigen::VectorXd u = problem.absoluteDisplacement(
        held.held ? held.at(k)
                  : freeDisplacementAt(problem, *factor, result.interface.lambda.col(k), k,
                                       workspaces[static_cast<std::size_t>(thread)]),
        k);
    Eigen::MatrixXd force, state;
    contactFields(problem, result, states, k, force, state);
    const FrameFields fields = frameFields(problem, u, force, state, layout.bodies);
    for (int b = 0; b < layout.parts(); ++b) {
      AtomicFile file(dir / layout.dataSet(problem, k, b).file);
      if (layout.grid) layout.grid->write(file.stream(), fields.nodal, fields.cells);
      else writeBlock(file.stream(), layout.blocks[static_cast<std::size_t>(b)], fields.nodal, fields.cells);
      file.commit();
    }
  });
  std::vector<PvdDataSet> frames;
  for (int k : steps)
    for (int b = 0; b < layout.parts(); ++b) frames.push_back(layout.dataSet(problem, k, b));
  writeFileAtomically(dir / "solution.pvd", pvdDocument(frames));
  return held.held ? 0 : static_cast<long>(steps.size());
}

void writeRunOutputs(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                     const RunInfo& info, const OutputSpec& output, PreparedOperators& operators) {
  const auto start = std::chrono::steady_clock::now();
  ensureWritableDirectory(dir);
  {
    AtomicFile file(dir / "reactions.csv");
    writeReactionsCsv(file.stream(), problem, result);
    file.commit();
  }
  {
    AtomicFile file(dir / "contact.csv");
    writeContactCsv(file.stream(), problem, result);
    file.commit();
  }
  writeFileAtomically(dir / "history.csv", historyCsv(result.summary));
  // The VTU writer refuses non-finite values: a run that broke down numerically gets no VTU series.
  WriterCounts writer;
  if (output.vtu && result.interface.lambda.allFinite() && result.interface.v.allFinite())
    writer.sparse_solves = writeSolutionSeries(dir, problem, result, output.vtu_stride, output.vtu_precision, operators);
  writer.seconds = secondsSince(start);
  writeFileAtomically(dir / "summary.json",  // last: marks a complete run
                      summaryJson(problem, result.summary, info, operators.preparations(), writer));
}

}  // namespace stc
