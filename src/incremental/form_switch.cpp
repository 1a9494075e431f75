#include "stcontact/incremental/form_switch.hpp"

#include <algorithm>
#include <sstream>

namespace stc {
namespace {
// Columns solved to weigh a column's Krylov iterations before switching: one chunk's worth, few
// against the hundreds of the zone, and kept if the march switches.
constexpr int kProbeColumns = 16;
}  // namespace

FormSwitch::FormSwitch(const Problem& problem, const SpdSolver& stiffness, std::vector<int> zone,
                       LearnColumns learn_columns)
    : problem_(problem),
      stiffness_(stiffness),
      zone_(std::move(zone)),
      learn_columns_(std::move(learn_columns)),
      whole_(problem, stiffness),
      delassus_(problem, stiffness),
      cone_(problem, delassus_),
      krylov_start_(krylov()) {}

InstantOutcome FormSwitch::solve(int k, const Eigen::VectorXd& lambda_previous, const Eigen::VectorXd& v_previous,
                                 const IncrementalOptions& options) {
  if (!switched_at_ && switchesBefore(k)) switchToInterface(k);
  if (!switched_at_) return whole_.solve(k, lambda_previous, v_previous, options.tolerance, options.max_newton_iterations);
  return cone_.solveInstant(v0_.col(k), lambda_previous, v_previous, options);
}

long FormSwitch::columnsLeft() const {
  return columnSolves(problem_, zone_.size()) - probe_columns_ + static_cast<long>(problem_.loads.size());
}

bool FormSwitch::switchesBefore(int k) {
  const int m = problem_.numSteps();
  at_switch_ = {k, whole_.solves(), krylov() - krylov_start_ - probe_krylov_};
  if (!interfaceIsCheaper(k, m, columnsLeft(), at_switch_, per_column_)) return false;
  if (per_column_) return true;
  const int d = problem_.contact.dimension;
  probe_nodes_ = std::min(zone_.size(), static_cast<std::size_t>((kProbeColumns + d - 1) / d));
  const long long before = krylov();
  const int solves_before = delassus_.sparseSolves();
  learn_columns_(delassus_, std::vector<int>(zone_.begin(), zone_.begin() + static_cast<std::ptrdiff_t>(probe_nodes_)));
  probe_krylov_ = krylov() - before;
  probe_columns_ = delassus_.sparseSolves() - solves_before;
  per_column_ = probe_columns_ > 0 ? static_cast<double>(probe_krylov_) / probe_columns_ : 0.0;
  return interfaceIsCheaper(k, m, columnsLeft(), at_switch_, per_column_);
}

void FormSwitch::switchToInterface(int k) {
  learn_columns_(delassus_, std::vector<int>(zone_.begin() + static_cast<std::ptrdiff_t>(probe_nodes_), zone_.end()));
  v0_ = freeInterfaceResponse(problem_, stiffness_);
  cone_.prepare(zone_);
  switched_at_ = k;
}

int FormSwitch::solves() const {
  return whole_.solves() + delassus_.sparseSolves() + (switched_at_ ? static_cast<int>(problem_.loads.size()) : 0);
}

std::vector<std::string> FormSwitch::remarks() const {
  std::ostringstream out;
  const MarchCost& c = at_switch_;
  const double per_instant = c.instants > 0 ? static_cast<double>(c.solves) / c.instants : 0.0;
  const double per_solve = c.solves > 0 ? static_cast<double>(c.krylov) / static_cast<double>(c.solves) : 0.0;
  out.precision(3);
  if (switched_at_) {
    out << "whole-body form for the first " << *switched_at_ << " instants (" << c.solves << " solves, "
        << per_instant << " an instant, " << per_solve << " Krylov iterations each), then the interface form: "
        << "the instants left outweighed the columns of the " << zone_.size() << " nodes within reach ("
        << per_column_.value_or(0.0) << " Krylov iterations each)";
    return {out.str(), cone_.systemsRemark(), delassus_.remark(problem_.contact.size())};
  }
  out << "whole-body form: " << whole_.solves() << " sparse solves with dofs held";
  if (per_column_)
    out << "; " << probe_columns_ << " columns solved to weigh the interface form (" << *per_column_
        << " Krylov iterations each) kept it";
  return {out.str()};
}

}  // namespace stc
