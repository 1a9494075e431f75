#pragma once
// A scaling study (`stcontact scaling`, docs/scaling.md): the comparison of
// strategies repeated over a mesh series (contact nodes on the arc, at the scene's instants) and a
// time series (instants m, at the scene's mesh); per strategy, the time to first reach one true
// error at every size, its growth exponent on log-log axes, where it beats the incremental solver,
// and what grows in memory.
#include <optional>
#include <string>
#include <vector>

#include "stcontact/studies/comparison.hpp"
#include "stcontact/studies/growth_fit.hpp"

namespace stc {

/// Mesh series: sizes are dofs (arc nodes vary); time series: sizes are instants m.
enum class Series { Mesh, Time };

const char* toString(Series series);

/// One size of the study: the comparison run at it (compare's measurements and report).
struct ScalingPoint {
  int mesh_size = 0;  ///< the generator's size parameter (ScalingStudy::mesh_parameter)
  int dimension = 2;  ///< d: interface rows per contact node
  int free_dofs = 0;
  double factor_nonzeros = 0.0;  ///< entries of the Cholesky factor of K_ff
  bool in_mesh_series = false;
  bool in_time_series = false;
  Comparison comparison;  ///< n_dofs, n_contact_nodes, n_steps, reference_s, strategies

  bool in(Series series) const { return series == Series::Mesh ? in_mesh_series : in_time_series; }
  /// The series' size: dofs (mesh) or instants m (time).
  double size(Series series) const;
  const StrategyMeasurement* strategy(const std::string& solver) const;
  /// The solve at tolerance of `m` over the incremental solver's at this size (NaN when either was
  /// not run).
  double timeRatioAtTolerance(const StrategyMeasurement& m) const;
};

struct ScalingStudy {
  std::string scene_name, scene_file, command;
  /// The generator key the mesh series varies: "arc_nodes" (half_disc, half_disc_slab) or
  /// "divisions" (half_ball).
  std::string mesh_parameter = "arc_nodes";
  double target_error = 1e-4;
  double tolerance = 0.0;  ///< on the error estimate
  int repeats = 1;
  /// Whether each size also measures the time to first reach the target (the error run and its
  /// timed repeats, a diagnostic); false (--only-at-tolerance): the solves at tolerance alone, and
  /// the fits, crossovers and plots on their times.
  bool first_reach = true;
  std::optional<double> time_cap_s;
  std::vector<std::string> solvers;
  std::vector<ScalingPoint> points;  ///< in the order run
  RunEnvironment environment;
  std::string load_after, memory_method;
  double run_s = 0.0;  ///< the whole study
};

/// The points of `series`, by increasing size.
std::vector<const ScalingPoint*> seriesPoints(const ScalingStudy& study, Series series);

/// The median work of `solver` to first reach the study's target at `point` (empty wall_s: not reached).
Reach reachAt(const ScalingStudy& study, const ScalingPoint& point, const std::string& solver);

/// "reached", or why not: "time cap", "iteration limit", "stagnated", "converged above the target",
/// "numerical issue", "not run".
std::string reachStatus(const ScalingStudy& study, const ScalingPoint& point, const std::string& solver);

/// The time a series is fitted on: the median time to first reach the target (study.first_reach),
/// else the median solve at tolerance when it converged on its estimate; empty where there is none.
std::optional<double> fittedTime(const ScalingStudy& study, const ScalingPoint& point, const std::string& solver);

/// Growth exponent of one strategy's time to the target over one series.
struct SeriesFit {
  std::string solver;
  Series series = Series::Mesh;
  int sizes = 0;          ///< sizes in the series
  int sizes_reached = 0;  ///< sizes where the target was reached: the fit uses only those
  std::optional<PowerLawFit> fit;  ///< empty with fewer than two reached sizes
};

SeriesFit fitSeries(const ScalingStudy& study, const std::string& solver, Series series);

/// Where `solver` beats the incremental solver at the target along one series.
struct Crossover {
  std::string solver;
  Series series = Series::Mesh;
  std::vector<double> time_ratio;        ///< per size of the series: solver / incremental (NaN: missing)
  std::optional<double> first_faster;    ///< the smallest size where the ratio is below 1
  /// Where the two fitted laws cross (extrapolated when outside the sizes measured); empty when
  /// a fit is missing or the exponents are equal.
  std::optional<double> fitted_crossing;
  /// Whether the solver is faster beyond fitted_crossing (its exponent is the smaller one).
  bool faster_beyond = false;
};

Crossover crossoverAgainstIncremental(const ScalingStudy& study, const std::string& solver, Series series);

/// Growth of a strategy's peak memory between consecutive sizes of the time series, per instant,
/// in bytes and in the units that could grow with m (docs/method.md §2: interface histories d n_C doubles
/// per instant; a displacement field n_free doubles per instant).
struct MemorySlope {
  int m_from = 0, m_to = 0;
  double bytes_per_instant = 0.0;
  double interface_arrays = 0.0;  ///< bytes_per_instant / (8 · d n_C)
  double free_dof_fields = 0.0;   ///< bytes_per_instant / (8 · n_free)
};

/// One slope per pair of consecutive time-series sizes where both peaks are known.
std::vector<MemorySlope> memorySlopes(const ScalingStudy& study, const std::string& solver);

/// Memory that the model predicts at one size, in MB (8-byte doubles).
struct MemoryEstimate {
  double factor_mb = 0.0;              ///< Cholesky factor of K_ff (or K + BᵀkB, same pattern)
  double interface_history_mb = 0.0;   ///< one d n_C × m history
  double displacement_history_mb = 0.0;  ///< one n_free × m history
  double delassus_mb = 0.0;            ///< dense (d n_C)² Delassus matrix (the 2D incremental solver)
  /// The dense Bᵀ and K_ff⁻¹ Bᵀ (n_free × d n_C each) that the dense Delassus matrix W = B K_ff⁻¹ Bᵀ
  /// is formed from (CondensedInterface::build, the 2D incremental solver).
  double condensation_mb = 0.0;
  double time_matrix_mb = 0.0;         ///< one dense m × m matrix
};

MemoryEstimate estimateMemory(const ScalingPoint& point);

}  // namespace stc
