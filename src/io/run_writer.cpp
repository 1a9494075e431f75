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
#include "stcontact/core/threads.hpp"
#include "stcontact/io/atomic_file.hpp"
#include "stcontact/io/body_blocks.hpp"
#include "stcontact/io/contact_tables.hpp"
#include "stcontact/io/frame_fields.hpp"
#include "stcontact/io/json_writer.hpp"
#include "stcontact/io/solution_file.hpp"
#include "stcontact/io/vtu_writer.hpp"
#include "stcontact/linalg/ranks.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/mesh/connected_parts.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"

namespace stc {
namespace {

// vtu/step_NNNNN.vtu, or vtu/step_NNNNN_body<b>.vtu for body b of several.
std::string frameName(int k, int body = -1) {
  char name[48];
  if (body < 0) std::snprintf(name, sizeof name, "vtu/step_%05d.vtu", k);
  else std::snprintf(name, sizeof name, "vtu/step_%05d_body%d.vtu", k, body);
  return name;
}

VtuGrid gridOf(const Problem& problem, FieldPrecision precision) {
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

FrameLayout frameLayout(const Problem& problem, FieldPrecision precision) {
  if (!problem.contact.isPair()) return {gridOf(problem, precision), {}, {}};
  const std::vector<int> part = partOfNodes(problem.body);
  Eigen::MatrixXd codes(1, static_cast<Eigen::Index>(part.size()));
  for (std::size_t i = 0; i < part.size(); ++i) codes(0, static_cast<Eigen::Index>(i)) = part[i];
  return {std::nullopt, bodyBlocks(problem.body, part, precision), std::move(codes)};
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
      .add("incremental_form", summary.incremental_form.empty() ? std::nullopt
                                                                : std::optional<std::string>(summary.incremental_form))
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
                         int stride, FieldPrecision precision, PreparedOperators& operators) {
  ensureWritableDirectory(dir / "vtu");
  const int threads = threadCount();
  FrameDisplacement displacement(problem, result, operators, threads);
  const ContactStateTable states = result.contactStates(problem.contact);
  const FrameLayout layout = frameLayout(problem, precision);
  const std::vector<int> steps = frameSteps(problem.numSteps(), frameStride(problem, stride));
  // The frames are independent: each thread forms (or solves) its own and writes its own files.
  parallelFor(static_cast<int>(steps.size()), threads, [&](int item, int thread) {
    const int k = steps[static_cast<std::size_t>(item)];
    const FrameFields fields = frameFields(problem, result, states, k, displacement.at(k, thread), layout.bodies);
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
  return displacement.solves() ? static_cast<long>(steps.size()) : 0;
}

long writeSolutionFile(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                       const RunTables& tables, const RunInfo& info, const OutputSpec& output, bool frames,
                       PreparedOperators& operators) {
  const int threads = threadCount();
  std::optional<FrameDisplacement> displacement;
  FramePlan plan;
  if (frames) {
    displacement.emplace(problem, result, operators, threads);
    plan = {frameSteps(problem.numSteps(), frameStride(problem, output.frame_stride)), &*displacement,
            output.field_precision};
  }
  // HDF5 writes to a path, not a stream: a temporary beside the file, renamed over it once closed.
  const std::filesystem::path file = dir / "solution.h5", temporary = dir / ".solution.h5.tmp";
  try {
    writeSolutionH5(temporary, problem, result, tables, {info.version, info.parameters_json, info.model_json}, plan);
    std::filesystem::rename(temporary, file);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  if (frames) writeFileAtomically(dir / "solution.xdmf", xdmfDocument("solution.h5", problem, plan.steps, output.field_precision));
  return frames && displacement->solves() ? static_cast<long>(plan.steps.size()) : 0;
}

void writeRunOutputs(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                     const RunInfo& info, const OutputSpec& output, PreparedOperators& operators) {
  const auto start = std::chrono::steady_clock::now();
  ensureWritableDirectory(dir);
  RunTables tables{interfaceTable(problem, result), {}};
  tables.reactions = reactionTable(problem, result, tables.interface);
  {
    AtomicFile file(dir / "reactions.csv");
    writeReactionsCsv(file.stream(), problem, tables.reactions);
    file.commit();
  }
  if (writesContactCsv(problem, output)) {
    AtomicFile file(dir / "contact.csv");
    writeContactCsv(file.stream(), problem, result, tables.interface);
    file.commit();
  }
  writeFileAtomically(dir / "history.csv", historyCsv(result.summary));
  // A run that broke down numerically gets no frames (the VTU writer refuses non-finite values).
  const bool frames = output.frames && result.interface.lambda.allFinite() && result.interface.v.allFinite();
  WriterCounts writer;
  writer.sparse_solves = writeSolutionFile(dir, problem, result, tables, info, output, frames && output.format == OutputFormat::Hdf5, operators);
  if (frames && output.format == OutputFormat::Vtu)
    writer.sparse_solves += writeSolutionSeries(dir, problem, result, output.frame_stride, output.field_precision, operators);
  writer.seconds = secondsSince(start);
  writeFileAtomically(dir / "summary.json",  // last: marks a complete run
                      summaryJson(problem, result.summary, info, operators.preparations(), writer));
}

bool writesContactCsv(const Problem& problem, const OutputSpec& output) {
  switch (output.contact_csv) {
    case ContactCsv::Always: return true;
    case ContactCsv::Never: return false;
    case ContactCsv::Auto: break;
  }
  return contactCsvBytes(problem) <= kSmallContactCsvBytes;
}

}  // namespace stc
