#pragma once
// Steps 2–3 of the reduced interface (reduced_interface.hpp): from a zone of contact nodes, solve the
// problem on its nodes alone (restrictToNodes: the same body and loads; one solve, single_solve.hpp),
// its iterates' true error measured with zero forces on the other rows (ErrorOnRows, which is their
// force in the restricted problem); then check the nodes left out: their normal displacement B_F u,
// one product with the separated displacement history, must keep g0 + v_n ≥ 0 at every instant. The
// solution then satisfies every condition of the whole problem (equilibrium with λ_F = 0, the contact
// law on the zone, open far nodes). Nodes that penetrate join the zone and the next round goes on
// from where the last stopped; after ReducedInterfaceOptions::rounds rounds, or a round that did not
// converge, the whole interface. A restricted round gets half of the iterations left.
// Each round's records count from the rounds before it (SolveInputs::origin); the summary records
// the rounds as a stage (SolveStage::ContactZone).
#include <Eigen/Core>
#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/error_measure.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::fas {

/// The true-error measure of a solve on some rows of the interface: the other rows carry no force.
class ErrorOnRows : public ErrorMeasure {
 public:
  /// `rows`: the rows solved, among `all_rows` rows of `whole`'s interface.
  ErrorOnRows(const ErrorMeasure& whole, std::vector<int> rows, int all_rows);
  double relativeError(const Eigen::MatrixXd& lambda) const override;
  bool defined() const override { return whole_.defined(); }
  /// Time spent in relativeError so far (the solve's clock leaves the measure out).
  double secondsSpent() const { return static_cast<double>(nanoseconds_.load()) * 1e-9; }

 private:
  const ErrorMeasure& whole_;
  std::vector<int> rows_;
  int all_rows_;
  mutable std::atomic<long long> nanoseconds_{0};
};

/// A history over the whole interface of which a round reads the rows of its zone: one held (a start
/// given, the first relaxation's ŝ; it must outlive the solve), or its rows formed on demand (the body
/// carried rigidly by the prescribed motion: no whole-interface history is held). None: s = 0.
class StartOnRows {
 public:
  using Form = std::function<InterfaceHistory(const std::vector<int>& rows)>;
  StartOnRows() = default;
  StartOnRows(const InterfaceHistory* held) : held_(held) {}  // NOLINT: a held history is a start
  explicit StartOnRows(Form form) : form_(std::move(form)) {}
  explicit operator bool() const { return held_ != nullptr || static_cast<bool>(form_); }
  /// Its rows `rows`, `steps` instants (zero without a start).
  InterfaceHistory rows(const std::vector<int>& rows, int steps) const;

 private:
  const InterfaceHistory* held_ = nullptr;
  Form form_;
};

/// Where the rounds start: ŝ on the whole interface (the first start, or the first relaxation's local
/// stage), and what was spent before (counted in the result). Each round reads the rows of its zone alone.
struct ZoneStart {
  StartOnRows hat;    ///< ŝ of the first round (none: s = 0)
  StartOnRows start;  ///< the first start (none: s = 0), for a whole-interface restart
  std::optional<IterationRecord> first;     ///< the record of a first relaxation, counted in the result
  double measure_s = 0.0;                   ///< time spent measuring its true error (not the solve's)
  std::string zone_origin;                  ///< where the zone came from, for the summary's message
  std::chrono::steady_clock::time_point clock = std::chrono::steady_clock::now();  ///< the result's time origin
};

/// The rounds from the contact nodes `zone` (indices, increasing) until no node left out penetrates
/// (solveAprioriOnContactZone after step 1; a test may give a zone that misses nodes).
SolveResult solveAprioriOnZone(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs,
                               std::vector<int> zone, const ZoneStart& from,
                               const SeparatedCoarseBasis& coarse_basis = {});

}  // namespace stc::fas
