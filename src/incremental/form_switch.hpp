#pragma once
// The whole-body march of solver.incremental_form = "auto" that turns to the interface form when its
// measured cost says so (form_choice.hpp, interfaceIsCheaper). "auto" chooses the whole-body form
// before the march on an assumed solve per instant; the presses make 1.3 to 1.7, but a history that
// slides back and forth makes more (the fretting history at 201 instants: 2.4 to 3.8 solves per
// instant from the first, GMRES at 39 Krylov iterations a solve against 26 for a cold column, and
// the whole-body form 2.7 times slower than the interface form at divisions 12, docs/scale.md, "The
// choice per scene"). Before each instant past the first few this weighs the whole-body form's rate
// over the instants left against the columns of the nodes within reach; when the columns look
// cheaper it solves a few of them to weigh a column's Krylov iterations, then, when they still are,
// the remaining columns and the free response, and marches on with the cone law on every node
// (cone_newton.hpp), from the last instant's forces and displacements. Both forms solve the same
// instant problem to the same tolerance, so the history is the same to it.
#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/incremental/cone_newton.hpp"
#include "stcontact/incremental/form_choice.hpp"
#include "stcontact/incremental/lazy_delassus.hpp"
#include "stcontact/incremental/newton_instant.hpp"
#include "stcontact/incremental/whole_body_newton.hpp"
#include "stcontact/options/incremental_options.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {

class FormSwitch {
 public:
  /// `zone`: the nodes within reach whose columns the interface form would solve; `learn_columns`
  /// solves the columns of the nodes it is given with the caller's progress notes.
  using LearnColumns = std::function<void(LazyDelassus&, const std::vector<int>&)>;
  FormSwitch(const Problem& problem, const SpdSolver& stiffness, std::vector<int> zone, LearnColumns learn_columns);

  /// Instant k from instant k − 1's forces and interface displacements, in the form of the moment.
  InstantOutcome solve(int k, const Eigen::VectorXd& lambda_previous, const Eigen::VectorXd& v_previous,
                       const IncrementalOptions& options);
  /// Sparse solves so far, in both forms.
  int solves() const;
  /// What the march did: the instant it switched at and what was weighed, then the interface form's
  /// Newton systems and Delassus columns; or that it kept the whole-body form.
  std::vector<std::string> remarks() const;
  /// The form that solved the last instants.
  IncrementalForm finalForm() const { return switched_at_ ? IncrementalForm::Interface : IncrementalForm::WholeBody; }

 private:
  /// Whether to switch before instant k (weighs, and solves the probe's columns the first time).
  bool switchesBefore(int k);
  /// The interface form's column solves not yet made: the zone's less the probe's, and the free response's.
  long columnsLeft() const;
  void switchToInterface(int k);
  long long krylov() const { return stiffness_.krylovCounts().iterations; }

  const Problem& problem_;
  const SpdSolver& stiffness_;
  std::vector<int> zone_;
  LearnColumns learn_columns_;
  WholeBodyLaw whole_;
  LazyDelassus delassus_;
  ConeLaw cone_;
  Eigen::MatrixXd v0_;                 ///< the free response, once switched
  long long krylov_start_ = 0;         ///< the backend's count when the march began
  long long probe_krylov_ = 0;         ///< the probe's Krylov iterations
  int probe_columns_ = 0;
  std::size_t probe_nodes_ = 0;        ///< the zone's first nodes, whose columns the probe solved
  std::optional<double> per_column_;   ///< Krylov iterations per column, once probed
  std::optional<int> switched_at_;
  MarchCost at_switch_;                ///< the whole-body march's cost as last weighed: at the switch, once switched
};

}  // namespace stc
