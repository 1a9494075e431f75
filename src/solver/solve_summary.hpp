#pragma once
// What every solver returns beside its solution (house style 3, after Ceres' Solver::Summary):
// a termination status, a message, and the per-iteration history written to history.csv.
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace stc {

enum class Termination { Converged, MaxIterations, Stagnated, NumericalIssue, StoppedByCallback };

const char* toString(Termination termination);

struct IterationRecord {
  int iteration = 0;
  int relaxations = 0;            ///< fine-level LATIN relaxations so far (global + local stage pairs)
  double indicator = 0.0;         ///< docs/method.md §2 η
  /// Estimate of the true error without the reference (src/solver/error_estimate.hpp); +∞ until
  /// the contraction rate is known. What the iterative solvers stop on.
  double error_estimate = 0.0;
  std::optional<double> error;    ///< true energy error against the reference, when known
  int rank = 0;                   ///< coarse / PGD basis size (0 for plain LATIN)
  int sparse_solves = 0;          ///< right-hand sides solved with the sparse factor so far
  double wall_s = 0.0;            ///< since the start of the solve
  /// E = Σ_k u_kᵀ K u_k of the iterate (src/solver/equilibrium_energy.hpp: the true error's
  /// normalisation), when the solver measures it for its estimate.
  std::optional<double> energy;
  /// Krylov iterations of the solve's linear solves so far on an iterative backend (0 on a direct
  /// one): RecordOrigin::krylov's reading when the record was made.
  long long krylov_iterations = 0;
};

/// A part of a solve beside its main iteration (docs/method.md §5): the solve on a sub-grid of
/// instants that nested iteration starts from, or the rounds of the reduced interface. The history's
/// counts and times include what a stage spent.
struct SolveStage {
  enum class Kind { SubGrid, ContactZone };
  Kind kind = Kind::SubGrid;
  std::string description;  ///< what it did: its clause of the summary's message
  int relaxations = 0;      ///< SubGrid: relaxations on the sub-grid
  int sparse_solves = 0;    ///< SubGrid: sparse solves of the sub-grid solve
  double wall_s = 0.0;      ///< SubGrid: its time
  int nodes = 0;            ///< ContactZone: contact nodes of the last round
  int rounds = 0;           ///< ContactZone: solves on a zone, the last one included
};

struct SolveSummary {
  std::string solver;
  Termination termination = Termination::MaxIterations;
  /// The whole message, as printed and written (summary.json): the reason, then the remarks, then
  /// each stage's description, joined by "; " (composeMessage).
  std::string message;
  std::string reason;                ///< why the iteration ended (IterationMonitor, the incremental march)
  std::vector<std::string> remarks;  ///< what the iteration reports beside (FAS: corrections rejected)
  std::vector<SolveStage> stages;    ///< parts of the solve beside its iteration, in order
  /// The incremental solver's form that solved ("interface" or "whole-body", solver.incremental_form:
  /// "auto"'s choice or the form asked for); empty for the other solvers.
  std::string incremental_form;
  std::vector<IterationRecord> history;
  int iterations = 0;
  int relaxations = 0;
  double indicator = 0.0;
  double error_estimate = 0.0;    ///< of the last iteration (0 for the exact incremental solver)
  std::optional<double> error;
  double wall_s = 0.0;
  /// Krylov iterations of the solve's linear solves on an iterative backend (0 on a direct one),
  /// counted by stc::solve (strategies/registry.hpp) from the operators it solved with.
  long long krylov_iterations = 0;

  bool converged() const { return termination == Termination::Converged; }
  /// Right-hand sides solved with a sparse factor over the whole solve (its stages included): the
  /// last record's count, 0 without records. The a posteriori basis's incremental solve and SVD,
  /// made before fas-aposteriori's iteration, are not in it.
  int sparseSolves() const { return history.empty() ? 0 : history.back().sparse_solves; }
  /// Counts `solves` made after the last iteration (a lift to nodes left out, spatial modes'
  /// responses) in the last record, so that sparseSolves() has them.
  void addSolvesAfterIteration(long solves) {
    if (!history.empty()) history.back().sparse_solves += static_cast<int>(solves);
  }
  /// Sets the last record's Krylov iterations to the solve's (krylov_iterations), so that history.csv's
  /// last row counts those made after the last iteration too, as it counts their solves.
  void countKrylovAfterIteration() {
    if (!history.empty()) history.back().krylov_iterations = krylov_iterations;
  }
  /// Sets `message` from the reason, the remarks and the stages.
  void composeMessage();
  /// Appends `stage` and its clause to the message.
  void addStage(SolveStage stage);
};

/// Called after every iteration; returning false stops the solve (Termination::StoppedByCallback).
using IterationCallback = std::function<bool(const IterationRecord&)>;

/// A line saying what a solve is doing outside its iterations (SolveInputs::phase_note,
/// src/solver/noted_phase.hpp).
using PhaseNote = std::function<void(const std::string&)>;

}  // namespace stc
