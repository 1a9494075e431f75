#include "stcontact/fas/coarse_step.hpp"

#include <Eigen/Cholesky>
#include <optional>

#include "stcontact/core/threads.hpp"
#include "stcontact/fas/coarse_zone.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/linalg/anderson.hpp"
#include "stcontact/linalg/dense_product.hpp"

namespace stc::fas {
namespace {

/// Below this reciprocal condition number I − M_F is taken as singular and no row is eliminated.
constexpr double kSingularSchur = 1e-12;

// One thread on small fields: each coarse iteration is dense products of r × rows by rows × m on
// this thread around a short local stage (~50 µs on the seed). On 2 threads every one of those
// local stages had to wake the pool's worker, asleep during the products, and hand over: that cost
// more than the split saves (bench_stages CoarseStep, seed: 8.3 ms on 1 thread, 13.2 ms on 2;
// docs/threads.md). From kThreadedFieldEntries (2^16) entries per field on, the local stages and the
// Anderson passes are long enough to share (alternated runs to 1e-4 or 1e-6, threaded against
// serial, every node iterated: 0.97 of the time at 201 contact nodes × 201 instants, 80 000 entries;
// 0.93 at 401, 0.92 at 801 and 1601; the seed mesh, 40 000 entries, 1.02). So the step sets its
// thread count by threadsForField (src/core/threads.hpp) on the field it iterates.

// The restricted linear stage ξ = (BY)ᵀ(W − W_s) with the far rows F eliminated (coarse_zone.hpp:
// the coarse problem takes them open, λ_F = 0, so W_F = k_F v_F with v_F = Bũ_F + BY_F ξ). On the
// zone's rows Z it reads
//   (I − M_F) ξ = (BY_Z)ᵀ (W_Z − W_s,Z) − (BY_F)ᵀ λ_F,   M_F = (BY_F)ᵀ k_F BY_F,
// λ_F the last global stage's forces there. YᵀAY = I with A = K + BᵀkB gives
// I − M_F = YᵀKY + (BY_Z)ᵀ k_Z BY_Z, SPD when K is; so ξ = mapᵀ (W_Z − W_s,Z) + shift.
struct ZoneLinearStage {
  Eigen::MatrixXd traces;  ///< BY_Z
  Eigen::MatrixXd map;     ///< BY_Z (I − M_F)⁻¹ (BY_Z without far rows)
  Eigen::MatrixXd shift;   ///< −(I − M_F)⁻¹ (BY_F)ᵀ λ_F, r × m (empty without far rows)

  /// False when I − M_F is singular to kSingularSchur (a motion that only the far rows see).
  bool build(const ContactInterface& contact, const Eigen::MatrixXd& BY, const CoarseZone& zone,
             const Eigen::MatrixXd& lambda) {
    traces = BY(zone.rows, Eigen::all);
    shift.resize(0, 0);
    if (zone.far_rows.empty()) {
      map = traces;
      return true;
    }
    const Eigen::MatrixXd far = BY(zone.far_rows, Eigen::all);
    Eigen::MatrixXd schur = Eigen::MatrixXd::Identity(BY.cols(), BY.cols());
    schur.noalias() -= far.transpose() * contact.search_direction(zone.far_rows).asDiagonal() * far;
    const Eigen::LLT<Eigen::MatrixXd> llt(schur);
    if (llt.info() != Eigen::Success || llt.rcond() < kSingularSchur) return false;
    shift = llt.solve(-(far.transpose() * lambda(zone.far_rows, Eigen::all)));
    if (!zone.rows.empty()) map = llt.solve(traces.transpose()).transpose();
    return true;
  }

  /// ξ from z = W_Z − W_s,Z (seed eq. (8) with R A P = I). An empty zone leaves the shift alone.
  void apply(const Eigen::MatrixXd& z, Eigen::MatrixXd& xi) const {
    if (z.rows() == 0) {
      xi = shift;
      return;
    }
    linalg::multiplyTransposed(map, z, xi);
    if (shift.size() > 0) xi += shift;
  }
};

// The restricted LATIN on the zone's rows (seed eqs. (5)–(8)) from the state w = W(ŝ), i_C linear
// stages and the i_C − 1 local stages between them: returns the last ξ and leaves in `w` the state
// it came from.
Eigen::MatrixXd iterateOnZone(const ContactInterface& zone_contact, const ZoneLinearStage& stage,
                              const FasOptions& options, const Eigen::MatrixXd& v0,
                              const Eigen::MatrixXd& W_s, Eigen::MatrixXd& w) {
  const Eigen::VectorXd& k = zone_contact.search_direction;
  const int iterations = options.coarseIterationsIn(zone_contact.dimension);
  Eigen::MatrixXd image(w.rows(), w.cols()), z, xi, dv(w.rows(), w.cols());
  std::optional<AndersonMixing> mixing;
  if (options.coarse_anderson > 0 && w.rows() > 0)
    mixing.emplace(options.coarse_anderson, k.cwiseSqrt().cwiseInverse());
  const ThreadCountScope threads(threadsForField(w.size()));
  for (int it = 0;; ++it) {
    z = w - W_s;
    stage.apply(z, xi);
    if (it + 1 >= iterations || w.rows() == 0) return xi;
    linalg::multiply(stage.traces, xi, dv);  // B Δu, seed eq. (7)
    // The trial v = Bũ + B Δu, λ = W(ŝ) − k v (seed eq. (5)), its local stage and the next state
    // W(ŝ) = λ̂ + k v̂, in one pass.
    latin::localStageOfTrial(zone_contact, v0, dv, w, nullptr, &image);
    if (mixing)
      mixing->nextTaking(w, image);
    else
      w.swap(image);
  }
}

}  // namespace

void coarseStep(const ContactInterface& contact, const CoarseSpace& space, const FasOptions& options,
                const InterfaceHistory& s, InterfaceHistory& hat) {
  const Eigen::VectorXd& k = contact.search_direction;
  const Eigen::MatrixXd& BY = space.interface();
  CoarseZone zone = options.coarse_zone ? coarseZone(contact, s, hat) : wholeInterface(contact);
  ZoneLinearStage stage;
  if (!stage.build(contact, BY, zone, s.lambda)) {
    zone = wholeInterface(contact);
    stage.build(contact, BY, zone, s.lambda);
  }
  if (options.start == CoarseStart::ZeroCorrection) hat.v = s.v;  // start (a): ŝ = (Bũ, λ̃)
  // On the zone: w = W(ŝ) = λ̂ + k v̂, the restricted LATIN's state; W_s = λ + k Bũ, the fine stage's.
  const auto on_zone = [&](const Eigen::MatrixXd& field) {
    return Eigen::MatrixXd(field(zone.rows, Eigen::all));
  };
  const ContactInterface zone_contact = restrictToNodes(contact, zone.nodes);
  const Eigen::VectorXd& k_zone = zone_contact.search_direction;
  const Eigen::MatrixXd v0 = on_zone(s.v);
  const Eigen::MatrixXd W_s = on_zone(s.lambda) + k_zone.asDiagonal() * v0;
  Eigen::MatrixXd w = on_zone(hat.lambda) + k_zone.asDiagonal() * on_zone(hat.v);
  const Eigen::MatrixXd xi = iterateOnZone(zone_contact, stage, options, v0, W_s, w);
  // The last trial on every node (the far ones open: W_F = k_F v_F) and its fine local stage.
  const ThreadCountScope threads(threadsForField(s.v.size()));
  const Eigen::MatrixXd dv = linalg::freshProduct(BY, xi);
  Eigen::MatrixXd W(s.v.rows(), s.v.cols());
  W(zone.rows, Eigen::all) = w;
  W(zone.far_rows, Eigen::all) =
      k(zone.far_rows).asDiagonal() * (s.v(zone.far_rows, Eigen::all) + dv(zone.far_rows, Eigen::all));
  latin::localStageOfTrial(contact, s.v, dv, W, &hat, nullptr);
}

}  // namespace stc::fas
