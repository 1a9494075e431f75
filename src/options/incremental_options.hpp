#pragma once
// Options of `incremental`, the reference solver (src/incremental/incremental_solver.hpp): the
// time-discrete problem solved instant by instant to round-off.
#include <array>
#include <string_view>
#include <utility>

#include "stcontact/options/option_fields.hpp"

namespace stc {

/// How the incremental solver solves an instant (src/incremental/incremental_solver.hpp).
enum class IncrementalForm {
  /// The form expected to make fewer sparse solves on this scene and backend
  /// (src/incremental/form_choice.hpp): the interface form but on a backend that holds dofs
  /// (cg-gamg), where the whole-body form is chosen when the instants are fewer than the interface
  /// form's column solves. The default.
  Auto,
  /// Semismooth Newton on the contact forces, with the interface condensed (the Delassus operator
  /// from the factor or from column solves): any scene, any backend.
  Interface,
  /// Active sets on the whole body's displacement, one warm sparse solve per iteration
  /// (src/incremental/whole_body_newton.hpp): a rigid obstacle whose contact rows read one dof, on
  /// a backend that holds dofs (cg-gamg).
  WholeBody,
};

inline constexpr std::array<std::pair<std::string_view, IncrementalForm>, 3> kIncrementalForms = {{
    {"auto", IncrementalForm::Auto},
    {"interface", IncrementalForm::Interface},
    {"whole-body", IncrementalForm::WholeBody},
}};

/// The form's name as solver.incremental_form spells it.
constexpr std::string_view nameOf(IncrementalForm form) { return keywordOf<IncrementalForm>(kIncrementalForms, form); }

struct IncrementalOptions {
  /// On ‖F‖∞ / S_k (src/incremental/incremental_solver.hpp): a few hundred ulps, so the reference is
  /// exact to round-off. In (0, 1).
  double tolerance = 1e-13;
  /// Per instant: the active set settles in a handful of steps; the cap only stops cycling.
  int max_newton_iterations = 50;
  /// Solve a 2D scene with the d-dimensional cone law and lazily computed Delassus columns
  /// (src/incremental/cone_newton.hpp), as every 3D scene is: the same solution to round-off, memory
  /// 8 d² n_C n_ever-closed bytes instead of 32 n_C².
  bool cone_law = false;
  /// The plane law on the contact nodes the prescribed motion can reach, checked after the solve
  /// (src/incremental/reach_zone.hpp): the same solution to round-off, d |Z| sparse solves and a
  /// dense W of (d |Z|)² instead of d n_C and (d n_C)². Without a prescribed translation, or when
  /// a node left out penetrates, every node is solved.
  bool zone_within_reach = true;
  /// solver.incremental_form: "auto", "interface" or "whole-body" (IncrementalForm).
  IncrementalForm form = IncrementalForm::Auto;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("tolerance", o.tolerance, inOpenUnit(), Exposure::Library);
    visit("max_newton_iterations", o.max_newton_iterations, atLeast(1), Exposure::Library);
    visit("cone_law", o.cone_law, anyFlag(), Exposure::Library);
    visit("zone_within_reach", o.zone_within_reach, anyFlag(), Exposure::Library);
    visit("incremental_form", o.form, Keywords<IncrementalForm>(kIncrementalForms));
  }
  void validate() const { validateFields(*this, "incremental"); }
};

}  // namespace stc
