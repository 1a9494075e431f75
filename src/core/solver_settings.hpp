#pragma once
// The solvers' settings in one place: the strategy names, the coarse start of FAS, and every
// default of their options. The scene's [solver] keys (src/scene/scene.hpp) and the options
// structs of the libraries (StoppingRule, LatinOptions, ControlledStageOptions, FasOptions,
// AprioriBasisOptions) start from these values; each struct validates its own fields.
#include <array>
#include <string_view>

namespace stc {

/// The strategies by their docs/interface.md names (what `solver.name`, --solver and --solvers take),
/// in the order of the comparison reports.
inline constexpr std::array<std::string_view, 5> kSolverNames = {"latin", "latin-pgd", "fas-aposteriori",
                                                                 "fas-apriori", "incremental"};

/// How the FAS coarse step starts from s̃ = (ũ, λ̃) (docs/method.md §4, "How the coarse step starts");
/// scene key solver.coarse_start = "zero" | "mismatch".
enum class CoarseStart {
  ZeroCorrection,     ///< (a) Δv̂ = 0, Δλ̂ = 0, taking v = Bũ (discards v̂ − Bũ)
  InterfaceMismatch,  ///< (b) Δv̂ = v̂ − Bũ, Δλ̂ = 0 (exact when the coarse space is the whole space)
};

namespace defaults {

/// On the estimate of the true error (src/solver/error_estimate.hpp; docs/method.md §2).
inline constexpr double tolerance = 1e-6;
/// Iterations (relaxations for FAS) at most: LATIN converges linearly and the seed needs a few
/// hundred at 1e-6; the hard cases that fail do not converge in 2000 either (docs/hard_cases.md).
inline constexpr int max_iterations = 2000;
inline constexpr int stagnation_window = 500;  ///< iterations without a 1% decrease of η before giving up
/// Instants per multi-right-hand-side solve (memory n_free × block; 16–32 measured fastest on the
/// seed scene, see src/linalg/spd_factor.cpp).
inline constexpr int block_size = 32;

// FAS (seed paper §4.2: ν1 = ν2 = 1, i_C = 15, N_res = 15; ν = 1 beat ν = 2 for both bases on the
// seed scene: docs/fas_aposteriori.md, docs/compare_bases.md). i_C = 8 with Anderson depth 2 instead
// of the seed's 15 plain coarse iterations: the same or fewer relaxations on the seed scene and every
// hard case, at about half the coarse work (docs/method.md §4, docs/floor.md).
inline constexpr int pre_relaxations = 1;      ///< ν1
inline constexpr int post_relaxations = 1;     ///< ν2
inline constexpr int coarse_iterations = 8;    ///< i_C
/// Anderson depth of the coarse step's restricted LATIN (0: plain iterations; fas/coarse_step.hpp).
inline constexpr int coarse_anderson = 2;
/// The coarse step iterates on its contact zone only, the open nodes clear of the obstacle
/// eliminated exactly (fas/coarse_zone.hpp; docs/method.md §4).
inline constexpr bool coarse_zone = true;
/// fas-apriori solves on the contact nodes that can touch, the others checked open afterwards
/// (fas/apriori/reduced_interface.hpp; docs/method.md §5).
inline constexpr bool reduce_interface = true;
/// fas-apriori on a grid of m instants starts from its own solution on every q-th instant,
/// q = ⌊(m − 1) / 200⌋, when q ≥ 2: a sub-grid of about 201 instants, the seed scene's grid
/// (fas/apriori/nested_in_time.hpp; docs/method.md §5). 0: never.
inline constexpr int nested_instants = 201;
/// θ of the FAS safeguard: a correction is rejected when the next indicator exceeds θ times the one
/// before the coarse step (fas/fas_options.hpp). It depends on the dimension and on the coarse space
/// (docs/method.md §4): on the plane meshes corrections that raise the indicator up to 1.8 times
/// often cut the true error, and those from fas-apriori's anticipated expansion up to 15 times (hard
/// case ν = 0.49); on the 3D hemisphere the ones that raise it raise the error too.
inline constexpr double safeguard_growth_2d = 1.5;
inline constexpr double safeguard_growth_3d = 1.0;
inline constexpr double anticipated_safeguard_growth_2d = 5.0;
/// `anticipated`: the coarse space comes from the anticipated expansion (BasisProvider::anticipates).
constexpr double safeguardGrowth(int dimension, bool anticipated = false) {
  if (dimension == 3) return safeguard_growth_3d;
  return anticipated ? anticipated_safeguard_growth_2d : safeguard_growth_2d;
}
inline constexpr int residual_vectors = 15;    ///< N_res of fas-aposteriori (seed §4.3)
inline constexpr CoarseStart coarse_start = CoarseStart::ZeroCorrection;
inline constexpr int svd_modes = 10;           ///< fas-aposteriori: leading energy-SVD modes
/// fas-apriori's coarse space: the pgd_max_modes leading energy modes of the a priori expansion and
/// the pgd_increment_modes leading modes of its change since the previous coarse step. 15 + 30:
/// fewer relaxations than 30 + 15 from the seed scene (20 against 18–20) to arc_nodes 401 (30
/// against 52, with no rejected correction) and 801 (66 against 366; docs/floor.md).
inline constexpr int pgd_max_modes = 15;
inline constexpr int pgd_increment_modes = 30;
/// fas-apriori: the coarse space from the anticipated expansion (fas/apriori/apriori_basis.hpp).
inline constexpr bool pgd_anticipate = true;
/// latin-pgd and fas-apriori: γ, the separated global stage's projection error kept below γ times the
/// previous gap ‖s − ŝ‖ (pgd/controlled_global_stage.hpp; docs/floor.md).
inline constexpr double pgd_gap_share = 0.05;

}  // namespace defaults
}  // namespace stc
