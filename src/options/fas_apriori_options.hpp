#pragma once
// Options of `fas-apriori` (docs/method.md §5): the two-level FAS on the separated global stage, its
// coarse space from the expansion built during the iterations (fas/apriori/apriori_basis.hpp), solved
// on the contact nodes that can touch (fas/apriori/reduced_interface.hpp) and, on long grids, from a
// solve on a sub-grid of instants (fas/apriori/nested_in_time.hpp).
#include "stcontact/options/fas_options.hpp"
#include "stcontact/options/option_fields.hpp"
#include "stcontact/options/separated_stage_options.hpp"

namespace stc::fas {

/// The a priori coarse space (fas/apriori/apriori_basis.hpp): the `modes` leading energy modes of the
/// expansion and the `increment_modes` leading modes of its change since the previous coarse step.
struct AprioriBasisOptions {
  /// 15 + 30: fewer relaxations than 30 + 15 from the seed scene (20 against 18–20) to arc_nodes 401
  /// (30 against 52, with no rejected correction) and 801 (66 against 366; docs/floor.md).
  int modes = 15;
  int increment_modes = 30;
  /// The coarse space from the expansion the next global stage would give (true) or the last one's.
  bool anticipate = true;
  /// Gaussian combinations of the next global stage's change ũ − ũ_last offered to the increment
  /// modes beside ũ − ũ_previous (with `anticipate`; 0: none). 8: relaxations to 1e-6 at 801 / 1601
  /// arc nodes 42 → 36 / 64 → 53, hemisphere at divisions 12 25 → 21; 4 to 32 within 3 of each
  /// other (docs/floor.md, "The step of the next relaxation in the increment modes").
  int step_samples = 8;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("pgd_max_modes", o.modes, atLeast(0));
    visit("pgd_increment_modes", o.increment_modes, atLeast(0));
    visit("pgd_anticipate", o.anticipate, anyFlag());
    visit("pgd_step_samples", o.step_samples, atLeast(0));
  }
  void validate() const;  ///< the fields, and at least one mode in all
};

/// The reduced interface (fas/apriori/reduced_interface.hpp; docs/method.md §5, "The reduced
/// interface"): the solve on the contact nodes that can touch, the others checked open afterwards.
struct ReducedInterfaceOptions {
  bool enabled = true;
  /// The zone's margin, a share of the first relaxation's largest normal jump δ (fas/coarse_zone.hpp):
  /// nodes closed, or within margin · δ of the obstacle (δ itself when that leaves none). Measured on
  /// the hard cases (relaxations to true error 1e-6, 14 cases without κ = 0.01): 377 at 1, 349 at
  /// 0.5, 362 at 0.25; at 0.25 the 3D hemisphere's zone misses nodes and takes a second round (44
  /// relaxations against 26 at 0.5): docs/floor.md, "The reduced interface".
  double margin = 0.5;
  /// The margin of the zone within reach of the prescribed motion (src/problem/prescribed_reach.hpp),
  /// in the scene's length unit: none. The rigid motion overestimates how far the nodes near the
  /// contact move; on the 15 hard cases and the four example scenes no node left out penetrated
  /// (docs/floor.md, "The zone before any solve").
  double reach_margin = 0.0;
  /// Restricted solves before the whole interface is solved.
  int rounds = 3;
  /// A zone above this share of the contact nodes is the whole interface.
  double whole_share = 0.75;
  /// γ: in 2D each round's search direction on a zone of n_Z nodes is k (n_Z / kSearchNodes)^γ when
  /// n_Z > kSearchNodes (k of the scene's law and κ; 0: k itself). The law k = κ E ℓ_i / L follows
  /// the stiffness of the coarsest modes, and on a finer 2D zone it leaves the smoother's k further
  /// below its nodes' (k_i W_ii at κ = 4: 0.33 on the seed, 0.061 at 801 arc nodes, 0.034 at 1601;
  /// 0.23 to 0.36 on the 3D scenes). With the zone from the first relaxation at the scene's k, the
  /// best scale on the hemicylinder's 801 and 1601 arc nodes and on the fretting pad at h = 0.0025
  /// (zones of 231, 459 and 133 nodes) is 1.5 to 2, 1.25 to 1.5 at h = 0.005 (67), 1 at 29 to 40:
  /// about (n_Z / 40)^¼. In 3D κ itself is best (docs/search_direction.md, "κ for fas-apriori on
  /// refined meshes").
  double search_growth = 0.25;
  static constexpr int kSearchNodes = 40;

  /// The factor of the search direction on a zone of `nodes` contact nodes in `dimension`.
  double searchScaleOn(int nodes, int dimension) const;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("reduce_interface", o.enabled, anyFlag());
    visit("zone_margin", o.margin, atLeast(0));
    visit("zone_reach_margin", o.reach_margin, atLeast(0));
    visit("zone_rounds", o.rounds, atLeast(1));
    visit("zone_whole_share", o.whole_share, inUnitClosed());
    visit("zone_search_growth", o.search_growth, atLeast(0));
  }
  void validate() const { validateFields(*this, "reduced interface"); }
};

/// Nested iteration in time (fas/apriori/nested_in_time.hpp; docs/method.md §5): on a grid of m
/// instants, first the same problem on every q-th instant, q = min(⌊(m − 1) / (instants − 1)⌋,
/// max_stride), when q ≥ 2.
struct NestedInTimeOptions {
  /// Instants of the sub-grid, about, at least: 201 is the seed scene's grid. 0: never.
  int instants = 201;
  /// The largest stride q: past it the start interpolated from the sub-grid is so far from the whole
  /// grid's solution that the whole grid's relaxations, each a pass over every instant, cost more than
  /// a finer sub-grid. Fretting history at divisions 16, 10 001 instants, τ = 1e-6: q = 50 (201
  /// instants) 32 relaxations on the whole grid, 39.6 s; q = 10 (1001 instants) 23 and 30.9 s; medians
  /// of 3, alternated (docs/scale.md, "The ladders on the fretting history"). 0: no bound.
  int max_stride = 10;
  /// The sub-grid's tolerance is at least this: below it the start it gives stops improving, its
  /// distance to the whole grid's solution is the time step's (seed scene at 401 arc nodes, 2001
  /// instants, every 10th instant: true error of the start 4.4e-4, 1.0e-4, 9.5e-5 at sub-grid
  /// tolerances 1e-3, 1e-4, 1e-5; docs/floor.md, "Long grids: nested iteration in time").
  double tolerance = 1e-4;
  /// Nested iteration on an iterative backend (cg-gamg) too, where each direction the sub-grid adds
  /// costs a Krylov solve and nothing is condensed. The sub-grid saves relaxations on the whole grid
  /// but adds directions beyond the zone's: fretting history, two ranks, CG + GAMG, τ = 1e-6, medians
  /// of 2 alternated, with / without: divisions 8 80 / 80 solves, 1.02 / 0.99 s; 12 172 / 172, 5.6 /
  /// 5.9 s; 16 322 / 306, 33.2 / 34.7 s; 20 659 / 471, 126 / 110 s; 30 (one run each) 1748 / 1497,
  /// 1150 / 1019 s (docs/scale.md, "Nested iteration in time on CG + GAMG"). A direct factor solves a
  /// direction at the price of two triangular solves, or none from its trailing block: nesting stays
  /// on there.
  bool on_iterative = false;

  /// Whether a backend that is direct (`direct`) or iterative nests at all; whether a grid does is
  /// nestedStride's (fas/apriori/nested_in_time.hpp: none when `instants` is 0).
  bool nestsOn(bool direct) const { return direct || on_iterative; }

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("nested_instants", o.instants, offOrAtLeast(2));
    visit("nested_max_stride", o.max_stride, offOrAtLeast(2));
    visit("nested_tolerance", o.tolerance, positive());
    visit("nested_on_iterative", o.on_iterative, anyFlag());
  }
  void validate() const { validateFields(*this, "nested iteration"); }
};

/// The separated fine level (docs/method.md §5): the separated global stage, the reduced interface
/// and nested iteration in time. `fas-apriori`'s, and `fas-aposteriori`'s when it runs on it
/// (fas_aposteriori_options.hpp), so that the two differ by their basis alone: one struct for both.
struct SeparatedFineLevelOptions {
  pgd::ControlledStageOptions stage;
  ReducedInterfaceOptions zone;
  NestedInTimeOptions nested;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    pgd::ControlledStageOptions::fields(o.stage, visit);
    ReducedInterfaceOptions::fields(o.zone, visit);
    NestedInTimeOptions::fields(o.nested, visit);
  }
  void validate() const {
    stage.validate();
    zone.validate();
    nested.validate();
  }
};

struct FasAprioriOptions : SeparatedFineLevelOptions {
  FasOptions fas;
  AprioriBasisOptions basis;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    FasOptions::fields(o.fas, visit);
    AprioriBasisOptions::fields(o.basis, visit);
    SeparatedFineLevelOptions::fields(o, visit);
  }
  void validate() const {
    fas.validate();
    basis.validate();
    SeparatedFineLevelOptions::validate();
  }
};

}  // namespace stc::fas
