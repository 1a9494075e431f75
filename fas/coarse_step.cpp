#include "fas/coarse_step.hpp"

#include <optional>

#include "latin/local_stage.hpp"
#include "src/core/threads.hpp"
#include "src/linalg/anderson.hpp"

namespace stc::fas {
namespace {

/// Entries per interface field (d n_C × m) from which the coarse step runs on threadCount() threads
/// (docs/threads.md, "The local stage by blocks of nodes").
constexpr Eigen::Index kThreadedCoarseEntries = 1 << 16;

}  // namespace

void coarseStep(const ContactInterface& contact, const CoarseSpace& space, const FasOptions& options,
                const InterfaceHistory& s, InterfaceHistory& hat) {
  const Eigen::VectorXd& k = contact.search_direction;
  const Eigen::MatrixXd& BY = space.interface();
  const Eigen::Index rows = s.v.rows(), cols = s.v.cols();
  if (options.start == CoarseStart::ZeroCorrection) hat.v = s.v;  // start (a): ŝ = (Bũ, λ̃)
  // w = W(ŝ) = λ̂ + k v̂, the state of the restricted LATIN; W_s = λ + k Bũ, the fine stage's.
  Eigen::MatrixXd w = hat.lambda, image(rows, cols), z(rows, cols), xi, dv(rows, cols);
  w.noalias() += k.asDiagonal() * hat.v;
  const Eigen::MatrixXd W_s = s.lambda + k.asDiagonal() * s.v;
  std::optional<AndersonMixing> mixing;
  if (options.coarse_anderson > 0) mixing.emplace(options.coarse_anderson, k.cwiseSqrt().cwiseInverse());
  // One thread on small fields: each coarse iteration is dense products of r × 2n_C by 2n_C × m on
  // this thread around a short local stage (~50 µs on the seed). On 2 threads every one of those
  // local stages had to wake the pool's worker, asleep during the products, and hand over: that cost
  // more than the split saves (bench_stages CoarseStep, seed: 8.3 ms on 1 thread, 13.2 ms on 2;
  // docs/threads.md). From kThreadedCoarseEntries entries per field on, the local stages and the
  // Anderson passes are long enough to share (alternated runs to 1e-4 or 1e-6, threaded against
  // serial: 0.97 of the time at 201 contact nodes × 201 instants, 80 000 entries; 0.93 at 401, 0.92
  // at 801 and 1601; the seed mesh, 40 000 entries, 1.02).
  const ThreadCountScope threads(rows * cols >= kThreadedCoarseEntries ? threadCount() : 1);
  for (int it = 0;; ++it) {
    z = w - W_s;
    xi.noalias() = BY.transpose() * z;  // seed eq. (8) with R A P = I
    dv.noalias() = BY * xi;             // B Δu, seed eq. (7)
    // The trial v = Bũ + B Δu, λ = W(ŝ) − k v (seed eq. (5)) and its local stage, in one pass: the
    // last iteration's ŝ is the result, the others' W(ŝ) = λ̂ + k v̂ the next state.
    const bool last = it + 1 >= options.coarse_iterations;
    latin::localStageOfTrial(contact, s.v, dv, w, last ? &hat : nullptr, last ? nullptr : &image);
    if (last) break;
    if (mixing) mixing->nextTaking(w, image);
    else w.swap(image);
  }
}

}  // namespace stc::fas
