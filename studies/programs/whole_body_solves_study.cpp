// What a whole-body semismooth Newton incremental solver would pay on CG + GAMG (the form of deal.II's
// step-41/42 and of dolfinx_contact; docs/scale.md, "The whole-body Newton form, estimated"), measured
// without building it. The incremental solver's semismooth Newton iterates do not depend on how each
// Newton system is solved: condensed on the interface (incremental_solver.hpp, the form built), or on
// the whole body with the active set imposed (closed nodes' normal dofs and sticking nodes' tangential
// dofs held, slipping nodes' tangential forces applied: Dirichlet and Neumann conditions, an SPD
// system for CG + GAMG). The whole-body form makes one such solve per Newton iteration. This study
// takes the incremental solution and, at every instant, makes the cheapest of them: one CG + GAMG
// solve of the whole body with that instant's converged active set imposed, from the previous
// instant's displacement, to the linear tolerance of a solve at τ (kRtolPerTolerance τ of ‖b‖). Its
// Krylov iterations on the instants in contact, beside the Newton iterations of the march, bound the
// whole-body form's Krylov work from below (a march that guessed every instant's active set at once);
// instants without contact are counted apart (a march gets them from the load responses). The GAMG
// set-up is timed apart: a march may reuse one hierarchy across steps.
// The check: the closed nodes' normal reactions K u − f of the whole-body solve are the incremental
// solver's λ_n to 1e-6 of the instant's largest force (exit 2 otherwise): the imposed active set
// reproduces the solution (a wrong one is off by the forces themselves; the solves' own error, at
// 1e-10 of ‖b‖, leaves at most 1.3e-8 on the scenes of docs/scale.md).
// Needs a build with PETSc and a rigid obstacle whose contact rows each read one dof (a plane
// along the axes: the half-ball's scenes); one process.
//   whole_body_solves_study examples/scenes/hemisphere_shallow.toml --sizes 12,20,30
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/linalg/prepare_spd_solver.hpp"
#include "stcontact/incremental/whole_body_newton.hpp"
#include "stcontact/linalg/ranks.hpp"
#include "stcontact/operators/rigid_body_modes.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/studies/programs/study_program.hpp"

namespace {

using Sparse = Eigen::SparseMatrix<double>;

// The free dof each contact row reads and its coefficient (−1 for a held row, which reads none).
using RowDofs = stc::ContactRowDofs;

RowDofs rowDofs(const stc::ContactInterface& contact) {
  if (contact.isPair())
    throw stc::InputError("whole_body_solves_study needs a rigid obstacle, not two bodies in contact");
  RowDofs out = stc::contactRowDofs(contact.B);
  for (std::size_t row = 0; row < out.dof.size(); ++row)
    if (out.dof[row] == -2)
      throw stc::InputError("whole_body_solves_study needs a rigid obstacle whose contact rows read one dof each "
                            "(a plane along the axes); row " + std::to_string(row) + " reads more");
  return out;
}

// Instant k's converged active set as conditions on the free dofs: held (closed normals, sticking
// tangents) at the incremental solution's displacement, loaded (slipping tangents) with its force.
struct ActiveSet {
  std::vector<char> held;
  Eigen::VectorXd held_value, load;
  std::vector<int> closed_normal_rows;
};

ActiveSet activeSetAt(const stc::Problem& problem, const RowDofs& rows, const stc::InterfaceHistory& solution, int k) {
  const stc::ContactInterface& contact = problem.contact;
  const int d = problem.dimension, n = problem.numFreeDofs();
  ActiveSet a{std::vector<char>(static_cast<size_t>(n), 0), Eigen::VectorXd::Zero(n), problem.load(k), {}};
  for (int i = 0; i < contact.size(); ++i) {
    const int rn = contact.normalRow(i);
    const double normal = solution.lambda(rn, k);
    if (!(normal > 0.0)) continue;  // open: λ = 0, no condition
    a.closed_normal_rows.push_back(rn);
    const bool sticks = solution.lambda.block(rn + 1, k, d - 1, 1).norm() < contact.friction * normal * (1.0 - 1e-9);
    for (int r = rn; r < rn + d; ++r) {
      const int dof = rows.dof[static_cast<size_t>(r)];
      const double c = rows.coefficient[r];
      if (dof < 0) continue;
      if (r == rn || sticks) {
        a.held[static_cast<size_t>(dof)] = 1;
        a.held_value[dof] = solution.v(r, k) / c;
      } else {
        a.load[dof] += c * solution.lambda(r, k);  // Bᵀ λ_t of a slipping node
      }
    }
  }
  return a;
}

// K_RR and b_R = f_R − K_RD u_D on the dofs not held (`kept`, in order).
struct Reduced {
  std::vector<int> kept;
  Sparse K;
  Eigen::VectorXd b;
};

Reduced reduce(const Sparse& K, const ActiveSet& a) {
  const auto n = static_cast<int>(K.rows());
  std::vector<int> index(static_cast<size_t>(n), -1);
  Reduced out;
  for (int j = 0; j < n; ++j)
    if (!a.held[static_cast<size_t>(j)]) {
      index[static_cast<size_t>(j)] = static_cast<int>(out.kept.size());
      out.kept.push_back(j);
    }
  const auto m = static_cast<int>(out.kept.size());
  out.b.resize(m);
  for (int r = 0; r < m; ++r) out.b[r] = a.load[out.kept[static_cast<size_t>(r)]];
  std::vector<Eigen::Triplet<double>> entries;
  for (int col = 0; col < K.outerSize(); ++col)
    for (Sparse::InnerIterator it(K, col); it; ++it) {
      const int r = index[static_cast<size_t>(it.row())], c = index[static_cast<size_t>(col)];
      if (r < 0) continue;
      if (c >= 0) entries.emplace_back(r, c, it.value());
      else out.b[r] -= it.value() * a.held_value[col];
    }
  out.K.resize(m, m);
  out.K.setFromTriplets(entries.begin(), entries.end());
  return out;
}

struct Counts {
  int free_dofs = 0, instants = 0, contact_instants = 0, newton_iterations = 0, solves = 0;
  long long krylov_contact = 0, krylov_free = 0;
  double setup_s = 0.0, solve_s = 0.0, worst_reaction = 0.0;
};

// One solve of the reduced system from `u` (the previous instant's displacement, updated in place)
// to ‖b − K u‖ ≤ rtol ‖b‖; its Krylov iterations.
long long solveFrom(const Reduced& s, double rtol, const Eigen::MatrixXd& modes, Eigen::VectorXd& u, Counts& counts) {
  Eigen::VectorXd x(s.kept.size());
  for (size_t r = 0; r < s.kept.size(); ++r) x[static_cast<Eigen::Index>(r)] = u[s.kept[r]];
  const Eigen::VectorXd residual = s.b - s.K * x;
  long long iterations = 0;
  if (residual.norm() > rtol * s.b.norm()) {
    stc::LinearSolverOptions options;
    options.backend = stc::LinearBackend::CgGamg;
    options.rtol = std::min(0.5, rtol * s.b.norm() / residual.norm());  // CG from 0 on the residual
    options.max_iterations = 10000;
    stc::SpdSolverHints hints;
    hints.near_null_space = [&] { return Eigen::MatrixXd(modes(s.kept, Eigen::all)); };
    std::unique_ptr<stc::SpdSolver> solver;
    counts.setup_s += stc::study::secondsOf([&] { solver = stc::prepareSpdSolver(s.K, "K_RR", options, hints); });
    counts.solve_s += stc::study::secondsOf([&] { x += solver->solve(residual); });
    iterations = solver->krylovCounts().iterations;
    ++counts.solves;
  }
  for (size_t r = 0; r < s.kept.size(); ++r) u[s.kept[r]] = x[static_cast<Eigen::Index>(r)];
  return iterations;
}

// The closed normals' reactions against λ_n, relative to the instant's largest force.
double reactionError(const stc::Problem& problem, const RowDofs& rows, const ActiveSet& a,
                     const stc::InterfaceHistory& solution, const Eigen::VectorXd& u, int k) {
  const Eigen::VectorXd reaction = problem.stiffness_free * u - a.load;
  const double scale = solution.lambda.col(k).lpNorm<Eigen::Infinity>();
  double worst = 0.0;
  for (int rn : a.closed_normal_rows) {
    const double r = reaction[rows.dof[static_cast<size_t>(rn)]] / rows.coefficient[rn];
    worst = std::max(worst, std::abs(r - solution.lambda(rn, k)) / scale);
  }
  return worst;
}

int newtonIterations(const std::string& message) {
  std::smatch m;
  return std::regex_search(message, m, std::regex(R"((\d+) Newton iterations)")) ? std::stoi(m[1]) : -1;
}

Counts measure(const stc::Problem& problem, double tolerance) {
  const stc::SolveResult incremental = stc::solveIncremental(problem);
  if (!incremental.summary.converged()) throw std::runtime_error("the incremental solve: " + incremental.summary.message);
  const RowDofs rows = rowDofs(problem.contact);
  const Eigen::MatrixXd modes = stc::rigidBodyModesOfFreeDofs(problem);
  const double rtol = stc::LinearSolverOptions::kRtolPerTolerance * tolerance;
  Counts counts;
  counts.free_dofs = problem.numFreeDofs();
  counts.instants = problem.numSteps();
  counts.newton_iterations = newtonIterations(incremental.summary.message);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.numFreeDofs());
  for (int k = 0; k < problem.numSteps(); ++k) {
    const ActiveSet a = activeSetAt(problem, rows, incremental.interface, k);
    for (int j = 0; j < u.size(); ++j)
      if (a.held[static_cast<size_t>(j)]) u[j] = a.held_value[j];
    const long long its = solveFrom(reduce(problem.stiffness_free, a), rtol, modes, u, counts);
    const bool contact = !a.closed_normal_rows.empty();
    counts.contact_instants += contact;
    (contact ? counts.krylov_contact : counts.krylov_free) += its;
    counts.worst_reaction = std::max(counts.worst_reaction, reactionError(problem, rows, a, incremental.interface, u, k));
  }
  return counts;
}

std::string table(const std::vector<std::pair<int, Counts>>& sizes) {
  std::ostringstream out;
  out << "| divisions | free dofs | instants | in contact | Newton its | Krylov its in contact | per instant in contact | "
         "Krylov its without contact | GAMG set-up s per solve | s per solve | reaction error |\n"
         "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
      << std::setprecision(3);
  for (const auto& [divisions, c] : sizes) {
    const double solves = std::max(1, c.solves);
    out << "| " << divisions << " | " << c.free_dofs << " | " << c.instants << " | " << c.contact_instants << " | "
        << c.newton_iterations << " | " << c.krylov_contact << " | "
        << (c.contact_instants ? double(c.krylov_contact) / c.contact_instants : 0.0) << " | " << c.krylov_free << " | "
        << c.setup_s / solves << " | " << c.solve_s / solves << " | " << c.worst_reaction << " |\n";
  }
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The Krylov work of a whole-body Newton incremental solver on CG + GAMG, from the incremental solution"};
  stc::study::StudyOptions o;
  o.scene = std::string(STC_SOURCE_DIR) + "/examples/scenes/hemisphere_shallow.toml";
  o.out = "results/whole_body_solves";
  std::vector<int> sizes{8, 12};
  double tolerance = 1e-6;
  stc::study::addStudyOptions(app, o);
  app.add_option("--sizes", sizes, "mesh.divisions of each size")->delimiter(',')->capture_default_str();
  app.add_option("--tol", tolerance, "τ: the solves stop at kRtolPerTolerance τ (1e-4 τ) of ‖b‖")
      ->capture_default_str()
      ->check(CLI::Range(1e-12, 0.1));
  return stc::study::runStudy(app, o, argc, argv, [&] {
    if (!stc::petscBackendsBuilt()) throw stc::InputError("whole_body_solves_study needs a build with PETSc (cg-gamg)");
    if (stc::startRanks().size > 1) throw stc::InputError("whole_body_solves_study runs in one process");
    if (o.repeats != 1) throw stc::InputError("whole_body_solves_study counts iterations, which do not change between runs: no --repeats");
    std::vector<std::pair<int, Counts>> rows;
    bool agree = true;
    for (int divisions : sizes) {
      const Counts c = measure(stc::study::problemAtDivisions(o, divisions), tolerance);
      std::cerr << "divisions " << divisions << ": " << c.krylov_contact << " Krylov iterations on " << c.contact_instants
                << " instants in contact, reaction error " << c.worst_reaction << "\n";
      agree = agree && c.worst_reaction <= 1e-6;
      rows.emplace_back(divisions, c);
    }
    std::filesystem::create_directories(o.out);
    const std::string report = table(rows);
    std::ofstream(o.out / "whole_body_solves.md") << report;
    std::cout << report;
    return agree ? 0 : 2;
  });
}
