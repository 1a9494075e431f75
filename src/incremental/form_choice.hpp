#pragma once
// solver.incremental_form = "auto" (IncrementalOptions::form): the incremental solver's form chosen
// per scene and backend before the march, from the sparse solves each would make
// (docs/scale.md, "The whole-body form"):
//   interface form   d |Z| solves before the march on a backend without a trailing block (the
//                    Delassus columns of the nodes within reach, reach_zone.hpp), then none;
//   whole-body form  at least one warm solve per instant (1.3 to 1.7 measured on the presses,
//                    whole_body_newton.hpp), their Krylov iterations 0.7 to 0.9 of a cold column's.
// So the whole-body form where it can run (wholeBodyRefusal empty: a backend that holds dofs, rows
// that read one dof) and the instants m are fewer than the interface form's column solves,
//   m < d |Z|;
// the interface form elsewhere, and where no zone says what it would pay (the cone law then forms
// the columns of the nodes that close, as they close). Measured on CG + GAMG (docs/scale.md, "The
// choice per scene", scripts/incremental_forms.sh): at d |Z| / m = 0.073 (the fretting history) the
// interface form 11× faster, at 0.55 (the shallow press, 24k dofs) 1.2× faster; at 1.5 (the shallow
// press, 106k dofs) and 2.8 (the deep press, 24k dofs) the whole-body form 1.5× and 1.3× faster.
// The assumed solve an instant is the presses'; a history that slides back and forth makes several
// (the fretting history on 201 instants, d |Z| / m = 1.6: 2.4 to 3.8, the whole-body form 2.7×
// slower), so the whole-body march "auto" chose weighs its measured rate as it goes and turns to the
// interface form when the columns are the cheaper (interfaceIsCheaper, form_switch.hpp).
#include <optional>
#include <string>
#include <vector>

#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/options/incremental_options.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {

/// The form a run solves in, and why (the summary's remark when "auto" weighed the two forms: on a
/// backend that holds dofs; elsewhere the interface form is the only one and the reason is empty).
/// A whole-body form "auto" chose rests on the rule's assumed solve per instant: its march turns to
/// the interface form when its measured cost says so (interfaceIsCheaper, form_switch.hpp).
struct FormChoice {
  IncrementalForm form = IncrementalForm::Interface;
  std::string reason;
};

/// The interface form's column solves for `zone_nodes` nodes within reach: d |Z|.
long columnSolves(const Problem& problem, std::size_t zone_nodes);

/// The whole-body march's cost so far, for interfaceIsCheaper.
struct MarchCost {
  int instants = 0;       ///< instants solved
  long solves = 0;        ///< their sparse solves
  long long krylov = 0;   ///< the Krylov iterations of those solves
};

/// Instants a whole-body march solves before its cost per instant is weighed: the presses make 1.3
/// to 1.7 solves per instant, and a rate over fewer instants is mostly the first instant's.
inline constexpr int kInstantsBeforeWeighing = 8;

/// Before instant k of m, whether the interface form's `columns` column solves would cost less than
/// the whole-body form's measured cost per instant over the instants left:
///   (m − k) · (solves / instants) · (Krylov / solve)  >  columns · (Krylov / column).
/// Without `krylov_per_column` (no column solved yet) a column is weighed as a whole-body solve, and
/// the answer says whether solving a few columns to weigh them is worth it. False before
/// kInstantsBeforeWeighing instants.
bool interfaceIsCheaper(int k, int m, long columns, const MarchCost& so_far, std::optional<double> krylov_per_column);

/// `requested` when it is a form; for IncrementalForm::Auto the rule of the header on `stiffness`
/// and the zone within reach (none: every node).
FormChoice chooseIncrementalForm(IncrementalForm requested, const Problem& problem, const SpdSolver& stiffness,
                                 const std::optional<std::vector<int>>& zone);

}  // namespace stc
