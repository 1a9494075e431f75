// The linear backends' crossover (docs/linear_solvers.md): for the separated stage's operator
// A = K_ff + Bᵀ k B of a scene at several mesh sizes, each backend this build has (cholmod; mumps and
// cg-gamg with PETSc) prepares A and solves a block of interface right-hand sides Bᵀ Λ (Λ random,
// the shape of the separated stage's new directions). Reported per size and backend: the
// preparation's seconds, the seconds per right-hand side, Krylov iterations, the factor's entries
// and the process's resident-memory growth over the preparation and the solves; medians over
// --repeats, the backends alternated within each repeat. The check: every backend's solution agrees
// with CHOLMOD's (MUMPS's on several ranks, where CHOLMOD does not run) to 1e-6 relative (exit 2
// otherwise). Under an MPI launcher the ranks prepare and solve together (rank 0 reports, its
// memory growth the column's).
//   linear_backends_study examples/scenes/hemisphere.toml --sizes 8,12,16 --rhs 8 --repeats 3
//   mpirun -np 2 linear_backends_study --sizes 8,12,16 --rhs 8 --repeats 3
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/linalg/prepare_spd_solver.hpp"
#include "stcontact/linalg/ranks.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/operators/rigid_body_modes.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/studies/peak_memory.hpp"
#include "stcontact/studies/programs/study_program.hpp"
#include "stcontact/studies/work_precision.hpp"

namespace {

using stc::LinearBackend;

struct Sample {
  double prepare_s = 0.0, per_rhs_s = 0.0, growth_mb = 0.0, factor_entries = 0.0;
  double iterations = 0.0;  ///< Krylov iterations per right-hand side
  double difference = 0.0;  ///< ‖X − X_cholmod‖ / ‖X_cholmod‖
};

struct Row {
  int divisions = 0, free_dofs = 0, contact_nodes = 0;
  std::map<LinearBackend, std::vector<Sample>> samples;
};

// The backends named in `names` (every one when empty) that this build has and that run on
// `ranks`, the first direct one the one the others are compared with.
std::vector<LinearBackend> backendsOn(const stc::Ranks& ranks, const std::vector<std::string>& names) {
  std::vector<LinearBackend> out;
  for (const auto& [name, backend] : stc::kLinearBackends) {
    const bool asked = names.empty() || std::find(names.begin(), names.end(), name) != names.end();
    const bool runs = backend == LinearBackend::Cholmod ? ranks.size == 1 : stc::petscBackendsBuilt();
    if (backend != LinearBackend::Auto && asked && runs) out.push_back(backend);
  }
  return out;
}

// One backend on A: prepared, then the block B solved; the memory growth over both.
Sample measure(const stc::Problem& problem, const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
               LinearBackend backend, double rtol, Eigen::MatrixXd& X) {
  stc::LinearSolverOptions options;
  options.backend = backend;
  options.rtol = rtol;
  stc::SpdSolverHints hints;
  hints.near_null_space = [&problem] { return stc::rigidBodyModesOfFreeDofs(problem); };
  stc::PeakMemoryProbe memory;
  memory.reset();
  Sample s;
  std::unique_ptr<stc::SpdSolver> solver;
  s.prepare_s = stc::study::secondsOf([&] { solver = stc::prepareSpdSolver(A, "A", options, hints); });
  s.per_rhs_s = stc::study::secondsOf([&] { X = solver->solve(B); }) / static_cast<double>(B.cols());
  s.growth_mb = memory.sample().growthMb();
  s.factor_entries = solver->factorNonZeros();
  const stc::KrylovCounts counts = solver->krylovCounts();
  s.iterations = counts.solves ? static_cast<double>(counts.iterations) / static_cast<double>(counts.solves) : 0.0;
  return s;
}

double medianOf(const std::vector<Sample>& samples, double Sample::*field) {
  std::vector<double> values;
  for (const Sample& s : samples) values.push_back(s.*field);
  return stc::median(values);
}

std::string table(const std::vector<Row>& rows, const stc::Ranks& ranks) {
  std::ostringstream out;
  out << "| divisions | free dofs | contact nodes | backend | ranks | prepare s | s per rhs | Krylov its per rhs | "
         "factor entries | memory growth MB (rank 0) | difference to "
      << (ranks.size == 1 ? "cholmod" : "mumps") << " (nan: none measured) |\n|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
  out << std::setprecision(3);
  for (const Row& r : rows)
    for (const auto& [backend, samples] : r.samples)
      out << "| " << r.divisions << " | " << r.free_dofs << " | " << r.contact_nodes << " | " << stc::nameOf(backend)
          << " | " << ranks.size << " | " << medianOf(samples, &Sample::prepare_s) << " | " << medianOf(samples, &Sample::per_rhs_s) << " | "
          << medianOf(samples, &Sample::iterations) << " | " << medianOf(samples, &Sample::factor_entries) << " | "
          << medianOf(samples, &Sample::growth_mb) << " | " << medianOf(samples, &Sample::difference) << " |\n";
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The linear backends' preparation and solve times on a scene's K + B^T k B at several sizes"};
  stc::study::StudyOptions o;
  o.scene = std::string(STC_SOURCE_DIR) + "/examples/scenes/hemisphere.toml";
  o.out = "results/linear_backends";
  std::vector<int> sizes{8, 12};
  int rhs = 8;
  double rtol = 1e-10;
  stc::study::addStudyOptions(app, o);
  app.add_option("--sizes", sizes, "mesh.divisions of each size")->delimiter(',')->capture_default_str();
  app.add_option("--rhs", rhs, "interface right-hand sides per solve")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--rtol", rtol, "cg-gamg's relative residual")->capture_default_str();
  std::vector<std::string> names;
  app.add_option("--backends", names, "the backends to measure (default: every one this build runs)")
      ->delimiter(',')
      ->check(CLI::IsMember({"cholmod", "mumps", "cg-gamg"}));
  return stc::study::runStudy(app, o, argc, argv, [&] {
    const stc::Ranks ranks = stc::startRanks();
    std::vector<Row> rows;
    bool agree = true;
    for (int divisions : sizes) {
      const stc::Problem problem = stc::study::problemAtDivisions(o, divisions);
      const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(problem);
      std::srand(17);
      const Eigen::MatrixXd B = Eigen::MatrixXd(problem.contact.B.transpose() *
                                                Eigen::MatrixXd::Random(problem.contact.B.rows(), rhs));
      Row row{divisions, problem.numFreeDofs(), problem.contact.size(), {}};
      for (int r = 0; r < o.repeats; ++r) {
        Eigen::MatrixXd reference;
        for (LinearBackend backend : backendsOn(ranks, names)) {
          Eigen::MatrixXd X;
          Sample s = measure(problem, A, B, backend, rtol, X);
          if (reference.size() == 0 && backend != LinearBackend::CgGamg) reference = X;  // the first direct factor
          s.difference = reference.size() ? (X - reference).norm() / reference.norm() : std::nan("");
          agree = agree && !(s.difference > 1e-6);
          if (ranks.writes())
            std::cerr << "divisions " << divisions << " " << stc::nameOf(backend) << ": prepare " << s.prepare_s
                    << " s, " << s.per_rhs_s << " s per rhs, difference " << s.difference << "\n";
          row.samples[backend].push_back(s);
        }
      }
      rows.push_back(row);
    }
    if (!ranks.writes()) return agree ? 0 : 2;
    std::filesystem::create_directories(o.out);
    const std::string report = table(rows, ranks);
    std::ofstream(o.out / "linear_backends.md") << report;
    std::cout << report;
    return agree ? 0 : 2;
  });
}
