#include "stcontact/pgd/arpack_eigen.hpp"

#include <arpack/arpack.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <mutex>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

#include "stcontact/core/input_error.hpp"

namespace stc::pgd {
namespace {

// ARPACK's SAVE variables make it non-reentrant: one reverse-communication loop at a time.
std::mutex& arpackMutex() {
  static std::mutex mutex;
  return mutex;
}

arpack::which whichCode(ArpackWhich which) {
  switch (which) {
    case ArpackWhich::LargestAlgebraic: return arpack::which::largest_algebraic;
    case ArpackWhich::SmallestAlgebraic: return arpack::which::smallest_algebraic;
    case ArpackWhich::LargestMagnitude: return arpack::which::largest_magnitude;
  }
  return arpack::which::largest_algebraic;
}

[[noreturn]] void fail(const char* routine, int info, int nconv) {
  std::string message = std::string("ARPACK ") + routine + " returned INFO = " + std::to_string(info) + ": " +
                        arpackMessage(routine, info);
  if (info == 1) message += " (" + std::to_string(nconv) + " wanted Ritz values converged)";
  throw std::runtime_error(message);
}

}  // namespace

const char* arpackMessage(const char* routine, int info) {
  const bool saupd = std::string(routine) == "dsaupd";
  switch (info) {
    case 0: return "normal exit";
    case 1: return "maximum number of iterations taken (IPARAM(3)); raise max_restarts, subspace or tolerance";
    case 3: return "no shifts could be applied during a cycle of the implicitly restarted Arnoldi iteration; "
                   "one possibility is to increase NCV relative to NEV";
    case -1: return "N must be positive";
    case -2: return "NEV must be positive";
    case -3: return "NCV must be greater than NEV and less than or equal to N";
    case -4: return "the maximum number of Arnoldi update iterations allowed must be greater than zero";
    case -5: return "WHICH must be one of 'LM', 'SM', 'LA', 'SA' or 'BE'";
    case -6: return "BMAT must be one of 'I' or 'G'";
    case -7: return "length of private work array WORKL is not sufficient";
    case -8: return "error return from trid. eigenvalue calculation (LAPACK dsteqr)";
    case -9: return "starting vector is zero";
    case -10: return "IPARAM(7) must be 1, 2, 3, 4 or 5";
    case -11: return "IPARAM(7) = 1 and BMAT = 'G' are incompatible";
    case -12: return saupd ? "IPARAM(1) must be equal to 0 or 1" : "NEV and WHICH = 'BE' are incompatible";
    case -13: return "NEV and WHICH = 'BE' are incompatible";
    case -14: return "DSAUPD did not find any eigenvalues to sufficient accuracy";
    case -15: return "HOWMNY must be one of 'A' or 'S' if RVEC = .true.";
    case -16: return "HOWMNY = 'S' not yet implemented";
    case -17: return "DSEUPD got a different count of the number of converged Ritz values than DSAUPD got "
                     "(data modified between DSAUPD and DSEUPD?)";
    case -9999: return "could not build an Arnoldi factorization (IPARAM(5) returns its size)";
    default: return "unknown ARPACK error code";
  }
}

void ArpackOptions::validate(int n) const {
  const auto bad = [](const std::string& field, const std::string& value, const std::string& rule) {
    throw InputError("ARPACK option " + field + " = " + value + " is invalid: " + rule);
  };
  if (n < 2) bad("n (operator size)", std::to_string(n), "must be >= 2");
  if (eigenvalues < 1 || eigenvalues >= n)
    bad("eigenvalues", std::to_string(eigenvalues), "must be in [1, n - 1] with n = " + std::to_string(n));
  if (subspace != 0 && (subspace <= eigenvalues || subspace > n))
    bad("subspace", std::to_string(subspace),
        "must be 0 (automatic) or in (eigenvalues, n] = (" + std::to_string(eigenvalues) + ", " + std::to_string(n) +
            "]");
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance) || tolerance >= 1.0)
    bad("tolerance", std::to_string(tolerance), "must be in [0, 1) (0: machine precision)");
  if (max_restarts < 1) bad("max_restarts", std::to_string(max_restarts), "must be >= 1");
}

ArpackEigen::ArpackEigen(int n, ArpackOptions options) : n_(n), options_(options) {
  options_.validate(n);
  ncv_ = options_.subspace > 0 ? options_.subspace : std::min(n, 2 * options_.eigenvalues + 1);
  resid_.resize(n);
  v_.resize(static_cast<std::size_t>(n) * ncv_);
  workd_.resize(3 * static_cast<std::size_t>(n));
  workl_.resize(static_cast<std::size_t>(ncv_) * (ncv_ + 8));  // LWORKL ≥ NCV² + 8 NCV
  select_.resize(ncv_);
}

ArpackResult ArpackEigen::compute(const Operator& op) {
  std::lock_guard<std::mutex> lock(arpackMutex());
  // Starting vector: fixed-seed uniform entries, passed with INFO = 1 (dsaupd.f: "RESID contains
  // the initial residual vector"), instead of ARPACK's own generator whose state persists between calls.
  std::mt19937 engine(options_.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (double& r : resid_) r = uniform(engine);
  int iparam[11] = {};
  int ipntr[11] = {};
  iparam[0] = 1;                      // ISHIFT: exact shifts
  iparam[2] = options_.max_restarts;  // MXITER
  iparam[3] = 1;                      // NB: block size 1 (the only one implemented)
  iparam[6] = 1;                      // MODE 1: A x = λ x
  // dsaupd replaces TOL ≤ 0 by dlamch('EpsMach'), but the C binding passes TOL by value, so the
  // replaced value never comes back; dseupd must see the same value as dsaupd, or its recount of the
  // converged Ritz values differs and it returns INFO = -17. So we pass dlamch('EpsMach') ourselves:
  // LAPACK's relative machine precision with rounding, ε/2 = 2⁻⁵³ (dlamch.f).
  tol_ = options_.tolerance > 0.0 ? options_.tolerance : std::numeric_limits<double>::epsilon() / 2;
  iterate(op, iparam, ipntr);
  return extract(iparam, ipntr);
}

void ArpackEigen::iterate(const Operator& op, int iparam[11], int ipntr[11]) {
  const int nev = options_.eigenvalues, lworkl = static_cast<int>(workl_.size());
  int ido = 0, info = 1;
  for (;;) {
    arpack::saupd(ido, arpack::bmat::identity, n_, whichCode(options_.which), nev, tol_, resid_.data(), ncv_,
                  v_.data(), n_, iparam, ipntr, workd_.data(), workl_.data(), lworkl, info);
    if (ido == 99) break;
    if (ido != -1 && ido != 1)  // mode 1 only ever asks for y = OP x
      throw std::runtime_error("ARPACK dsaupd asked for an unexpected action IDO = " + std::to_string(ido));
    // IPNTR(1), IPNTR(2): 1-based offsets of x and y in WORKD.
    const Eigen::Map<const Eigen::VectorXd> x(workd_.data() + ipntr[0] - 1, n_);
    Eigen::Map<Eigen::VectorXd> y(workd_.data() + ipntr[1] - 1, n_);
    op(x, y);
  }
  if (info != 0) fail("dsaupd", info, iparam[4]);
}

ArpackResult ArpackEigen::extract(int iparam[11], int ipntr[11]) {
  const int nev = options_.eigenvalues, lworkl = static_cast<int>(workl_.size());
  const double sigma = 0.0;
  const int rvec = 1;  // LOGICAL .true.: Ritz vectors wanted
  Eigen::VectorXd d(nev);
  Eigen::MatrixXd z(n_, nev);
  int info = 0;
  arpack::seupd(rvec, arpack::howmny::ritz_vectors, select_.data(), d.data(), z.data(), n_, sigma,
                arpack::bmat::identity, n_, whichCode(options_.which), nev, tol_, resid_.data(), ncv_, v_.data(), n_,
                iparam, ipntr, workd_.data(), workl_.data(), lworkl, info);
  if (info != 0) fail("dseupd", info, iparam[4]);
  const int nconv = iparam[4];
  if (nconv < nev) fail("dsaupd", 1, nconv);

  // dseupd returns the Ritz values in ascending algebraic order; reorder from the wanted end.
  std::vector<int> order(nev);
  std::iota(order.begin(), order.end(), 0);
  const ArpackWhich which = options_.which;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (which == ArpackWhich::LargestAlgebraic) return d[a] > d[b];
    if (which == ArpackWhich::SmallestAlgebraic) return d[a] < d[b];
    return std::abs(d[a]) > std::abs(d[b]);
  });
  ArpackResult result;
  result.values.resize(nev);
  result.vectors.resize(n_, nev);
  for (int j = 0; j < nev; ++j) {
    result.values[j] = d[order[j]];
    result.vectors.col(j) = z.col(order[j]);
  }
  result.restarts = iparam[2];
  result.operator_applications = iparam[8];
  return result;
}

}  // namespace stc::pgd
