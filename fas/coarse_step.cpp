#include "fas/coarse_step.hpp"

#include "latin/local_stage.hpp"
#include "src/core/threads.hpp"

namespace stc::fas {

void coarseStep(const ContactInterface& contact, const CoarseSpace& space, const FasOptions& options,
                const InterfaceHistory& s, InterfaceHistory& hat, Eigen::MatrixXd& xi) {
  const Eigen::VectorXd& k = contact.search_direction;
  const Eigen::MatrixXd& BY = space.interface();
  const Eigen::MatrixXd lambda_tilde = hat.lambda;          // λ̃: forces of s̃ (local stage)
  const Eigen::MatrixXd residual = lambda_tilde - s.lambda;  // res̃ = Bᵀ(λ̃ − λ)
  Eigen::MatrixXd dv_hat = Eigen::MatrixXd::Zero(s.v.rows(), s.v.cols());
  if (options.start == CoarseStart::InterfaceMismatch) dv_hat = hat.v - s.v;
  Eigen::MatrixXd dl_hat = Eigen::MatrixXd::Zero(s.v.rows(), s.v.cols());
  InterfaceHistory trial;
  // One thread: each coarse iteration is dense products of r × 2n_C by 2n_C × m on this thread
  // around a short local stage (~50 µs on the seed). On 2 threads every one of those local stages
  // had to wake the pool's worker, asleep during the products, and hand over: that cost more than
  // the split saves (bench_stages CoarseStep, seed: 8.3 ms on 1 thread, 13.2 ms on 2; a worker
  // kept awake longer, 8.9 ms; serial here: 7.9 ms; docs/threads.md).
  const ThreadCountScope serial(1);
  for (int it = 0; it < options.coarse_iterations; ++it) {
    xi.noalias() = BY.transpose() * (residual + dl_hat + k.asDiagonal() * dv_hat);  // seed eq. (8), R A P = I
    trial.v.noalias() = BY * xi;                                                 // BΔu, seed eq. (7)
    trial.lambda = dl_hat - k.asDiagonal() * (trial.v - dv_hat);                 // Δλ, seed eq. (5)
    trial.v += s.v;
    trial.lambda += lambda_tilde;
    latin::localStage(contact, trial, hat);
    dv_hat = hat.v - s.v;
    dl_hat = hat.lambda - lambda_tilde;
  }
}

}  // namespace stc::fas
