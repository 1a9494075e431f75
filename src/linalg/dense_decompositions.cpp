#include "stcontact/linalg/dense_decompositions.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <optional>
#include <random>
#include <vector>

#ifdef EIGEN_USE_BLAS
// LAPACK's blocked Householder QR and the explicit thin Q, from the OpenBLAS the products use.
extern "C" {
void dgeqrf_(const int* m, const int* n, double* a, const int* lda, double* tau, double* work, const int* lwork,
             int* info);
void dorgqr_(const int* m, const int* n, const int* k, double* a, const int* lda, const double* tau, double* work,
             const int* lwork, int* info);
void dormqr_(const char* side, const char* trans, const int* m, const int* n, const int* k, const double* a,
             const int* lda, const double* tau, double* c, const int* ldc, double* work, const int* lwork, int* info);
void dgesvd_(const char* jobu, const char* jobvt, const int* m, const int* n, double* a, const int* lda, double* s,
             double* u, const int* ldu, double* vt, const int* ldvt, double* work, const int* lwork, int* info);
void dgesdd_(const char* jobz, const int* m, const int* n, double* a, const int* lda, double* s, double* u,
             const int* ldu, double* vt, const int* ldvt, double* work, const int* lwork, int* iwork, int* info);
}
#endif

namespace stc::linalg {
namespace {

template <class Decomposition>
Svd fromDecomposition(const Decomposition& d, unsigned vectors) {
  Svd svd;
  svd.values = d.singularValues();
  if (vectors & kThinU) svd.U = d.matrixU();
  if (vectors & kThinV) svd.V = d.matrixV();
  return svd;
}

#ifdef EIGEN_USE_BLAS
// LAPACK's dgeqrf of A (m × p) in place, the reflectors below its diagonal and their factors in
// `tau`, then `use(work, lwork)`, the routine that forms or applies them (it returns LAPACK's info):
// both are asked for their workspace first (lwork = −1, the size in work[0]) and then run with one
// that fits both. False when either fails.
template <class Use>
bool householderThen(Eigen::MatrixXd& A, Eigen::VectorXd& tau, Use&& use) {
  const int m = static_cast<int>(A.rows()), p = static_cast<int>(A.cols()), lda = std::max(m, 1);
  tau.resize(std::max(p, 1));
  int info = 0, query = -1;
  double size_qr = 0.0, size_use = 0.0;
  dgeqrf_(&m, &p, A.data(), &lda, tau.data(), &size_qr, &query, &info);
  use(&size_use, query);
  int lwork = static_cast<int>(std::max({size_qr, size_use, 1.0}));
  Eigen::VectorXd work(lwork);
  dgeqrf_(&m, &p, A.data(), &lda, tau.data(), work.data(), &lwork, &info);
  return info == 0 && use(work.data(), lwork) == 0;
}

// The first n columns of Q = H(1) H(2) ⋯ H(n), the reflectors of dgeqrf (LAPACK's dorgqr): the ones
// Eigen::HouseholderQR forms, applied in blocks of OpenBLAS products. On the range finders' shapes
// (201 to 987 rows, 20 to 100 columns) 0.28 to 0.92 of Eigen's time (bench/bench_dense.cpp).
bool lapackThinQ(Eigen::MatrixXd& A) {
  const int m = static_cast<int>(A.rows()), n = static_cast<int>(A.cols()), lda = std::max(m, 1);
  Eigen::VectorXd tau;
  return householderThen(A, tau, [&](double* work, int lwork) {
    int info = 0;
    dorgqr_(&m, &n, &n, A.data(), &lda, tau.data(), work, &lwork, &info);
    return info;
  });
}

// C ← H(1) ⋯ H(p) C for the reflectors of dgeqrf of A (m × p) (LAPACK's dormqr): with C = [0; I]
// the last m − p columns of the full Q, an orthonormal basis of the complement of A's range.
bool lapackApplyQ(Eigen::MatrixXd A, Eigen::MatrixXd& C) {
  const int m = static_cast<int>(A.rows()), p = static_cast<int>(A.cols()), n = static_cast<int>(C.cols());
  const int ld = std::max(m, 1);
  Eigen::VectorXd tau;
  return householderThen(A, tau, [&](double* work, int lwork) {
    int info = 0;
    dormqr_("L", "N", &m, &n, &p, A.data(), &ld, tau.data(), C.data(), &ld, work, &lwork, &info);
    return info;
  });
}

// A = U Σ Vᵀ for a tall A (rows ≥ cols) by dgesvd: its QR first, then the bidiagonal SVD of R by
// implicit QR iteration (LAPACK Users' Guide, "Singular Value Decomposition"); U and V thin, filled
// when asked for. False when the iteration did not converge.
bool lapackTallSvd(Eigen::MatrixXd A, bool want_u, bool want_v, Svd& svd) {
  const int m = static_cast<int>(A.rows()), n = static_cast<int>(A.cols()), lda = std::max(m, 1);
  svd.values.resize(n);
  if (want_u) svd.U.resize(m, n);
  Eigen::MatrixXd vt(want_v ? n : 1, want_v ? n : 1);
  const char jobu = want_u ? 'S' : 'N', jobvt = want_v ? 'S' : 'N';
  const int ldu = want_u ? m : 1, ldvt = static_cast<int>(vt.rows());
  double* u = want_u ? svd.U.data() : vt.data();  // not referenced for 'N'
  int info = 0, lwork = -1;
  double size = 0.0;
  dgesvd_(&jobu, &jobvt, &m, &n, A.data(), &lda, svd.values.data(), u, &ldu, vt.data(), &ldvt, &size, &lwork, &info);
  lwork = static_cast<int>(std::max(size, 1.0));
  Eigen::VectorXd work(lwork);
  dgesvd_(&jobu, &jobvt, &m, &n, A.data(), &lda, svd.values.data(), u, &ldu, vt.data(), &ldvt, work.data(), &lwork,
          &info);
  if (want_v) svd.V = vt.transpose();
  return info == 0;
}

// R = U Σ Vᵀ for a square R by LAPACK's dgesdd (bidiagonalisation, then divide and conquer on the
// bidiagonal: LAPACK Users' Guide, "Singular Value Decomposition"); U and Vᵀ only when `vectors`.
bool squareDivideAndConquer(Eigen::MatrixXd& R, bool vectors, Svd& svd, Eigen::MatrixXd& U, Eigen::MatrixXd& VT) {
  const int n = static_cast<int>(R.rows()), ld = std::max(n, 1);
  const char jobz = vectors ? 'S' : 'N';
  svd.values.resize(n);
  U.resize(vectors ? n : 1, vectors ? n : 1);
  VT.resize(U.rows(), U.cols());
  std::vector<int> iwork(8 * std::max(n, 1));
  int info = 0, lwork = -1;
  double size = 0.0;
  const int ldu = static_cast<int>(U.rows());
  dgesdd_(&jobz, &n, &n, R.data(), &ld, svd.values.data(), U.data(), &ldu, VT.data(), &ldu, &size, &lwork,
          iwork.data(), &info);
  lwork = static_cast<int>(std::max(size, 1.0));
  Eigen::VectorXd work(lwork);
  dgesdd_(&jobz, &n, &n, R.data(), &ld, svd.values.data(), U.data(), &ldu, VT.data(), &ldu, work.data(), &lwork,
          iwork.data(), &info);
  return info == 0;
}

// A = U Σ Vᵀ for a tall A (rows ≥ cols) by divide and conquer: A = Q R (dgeqrf), R = U_R Σ V_Rᵀ
// (dgesdd on the short side only), U = Q [U_R; 0] (dormqr), V = V_R. The QR iteration of dgesvd
// applies its rotations to the vectors one plane at a time; divide and conquer forms them in
// products: on a 950 × 2001 history asked for its left vectors, 0.4 of dgesvd's time.
bool lapackTallDivideAndConquer(Eigen::MatrixXd A, bool want_u, bool want_v, Svd& svd) {
  const int m = static_cast<int>(A.rows()), n = static_cast<int>(A.cols()), ld = std::max(m, 1);
  Eigen::VectorXd tau;
  if (want_u) svd.U = Eigen::MatrixXd::Zero(m, n);
  return householderThen(A, tau, [&](double* work, int lwork) {
    int info = 0;
    if (lwork != -1) {
      Eigen::MatrixXd R = A.topRows(n).triangularView<Eigen::Upper>(), U_R, VT_R;
      if (!squareDivideAndConquer(R, want_u || want_v, svd, U_R, VT_R)) return 1;
      if (want_v) svd.V = VT_R.transpose();
      if (!want_u) return 0;
      svd.U.topRows(n) = U_R;
    } else if (!want_u) {
      *work = 1.0;  // no workspace of its own besides dgesdd's
      return 0;
    }
    dormqr_("L", "N", &m, &n, &n, A.data(), &ld, tau.data(), svd.U.data(), &ld, work, &lwork, &info);
    return info;
  });
}

// M's SVD from that of the taller of M and Mᵀ (Mᵀ = V Σ Uᵀ) by `tall`: on a wide matrix dgesvd
// bidiagonalises all of it, on its transpose a square R of the short side.
template <class TallSvd>
std::optional<Svd> lapackSvd(const Eigen::MatrixXd& M, unsigned vectors, TallSvd&& tall) {
  const bool want_u = vectors & kThinU, want_v = vectors & kThinV;
  Svd svd;
  if (M.rows() >= M.cols()) {
    if (!tall(M, want_u, want_v, svd)) return std::nullopt;
    return svd;
  }
  if (!tall(M.transpose(), want_v, want_u, svd)) return std::nullopt;
  svd.U.swap(svd.V);
  return svd;
}
#endif

}  // namespace

Eigen::MatrixXd orthonormalColumns(const Eigen::MatrixXd& Y) {
#ifdef EIGEN_USE_BLAS
  if (Y.cols() > 0 && Y.cols() <= Y.rows()) {
    Eigen::MatrixXd Q = Y;
    if (lapackThinQ(Q)) return Q;
  }
#endif
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Y);
  return qr.householderQ() * Eigen::MatrixXd::Identity(Y.rows(), Y.cols());
}

Eigen::MatrixXd orthonormalComplement(const Eigen::MatrixXd& Q) {
  const Eigen::Index n = Q.rows(), p = Q.cols();
  if (p >= n) return Eigen::MatrixXd(n, 0);  // no block of an n × 0 matrix (UBSan: offset on null)
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n - p);
  C.bottomRows(n - p).setIdentity();
  if (p == 0) return C;
#ifdef EIGEN_USE_BLAS
  if (Eigen::MatrixXd applied = C; lapackApplyQ(Q, applied)) return applied;
#endif
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Q);
  return qr.householderQ() * C;
}

SymmetricEigen symmetricEigen(const Eigen::MatrixXd& M) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M);
  SymmetricEigen result;
  result.converged = eig.info() == Eigen::Success;
  result.values = eig.eigenvalues();
  result.vectors = eig.eigenvectors();
  return result;
}

Eigen::MatrixXd orthonormalIn(const Eigen::MatrixXd& V, const Eigen::SparseMatrix<double>& M, double drop) {
  if (V.cols() == 0) return V;
  const Eigen::MatrixXd MV = M * V;
  Eigen::MatrixXd G = V.transpose() * MV;
  G = 0.5 * (G + G.transpose()).eval();  // symmetric to the last bit before the eigensolver
  const SymmetricEigen eig = symmetricEigen(G);
  const Eigen::VectorXd& d = eig.values;  // ascending
  const double largest = d.maxCoeff();
  int keep = 0;
  for (Eigen::Index j = 0; j < d.size(); ++j) keep += d[j] > drop * largest;
  // Y = V Q_kept D_kept^{-1/2}: then YᵀMY = D^{-1/2} Qᵀ G Q D^{-1/2} = I.
  const Eigen::MatrixXd T = eig.vectors.rightCols(keep) * d.tail(keep).cwiseSqrt().cwiseInverse().asDiagonal();
  return V * T;
}

Svd singularValueDecomposition(const Eigen::MatrixXd& M, SvdMethod method, unsigned vectors) {
  unsigned options = 0;
  if (vectors & kThinU) options |= Eigen::ComputeThinU;
  if (vectors & kThinV) options |= Eigen::ComputeThinV;
#ifdef EIGEN_USE_BLAS
  if (method == SvdMethod::qr_iteration && M.size() > 0)
    if (std::optional<Svd> svd = lapackSvd(M, vectors, lapackTallSvd)) return *std::move(svd);
  if (method == SvdMethod::lapack_divide_and_conquer && M.size() > 0)
    if (std::optional<Svd> svd = lapackSvd(M, vectors, lapackTallDivideAndConquer)) return *std::move(svd);
#endif
  if (method == SvdMethod::jacobi || method == SvdMethod::qr_iteration)
    return fromDecomposition(Eigen::JacobiSVD<Eigen::MatrixXd>(M, options), vectors);
  return fromDecomposition(Eigen::BDCSVD<Eigen::MatrixXd>(M, options), vectors);
}

Eigen::MatrixXd gaussianSketch(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd omega(rows, cols);
  for (Eigen::Index j = 0; j < omega.size(); ++j) omega(j) = normal(rng);
  return omega;
}

Eigen::MatrixXd randomizedRange(const Eigen::MatrixXd& R, Eigen::Index samples, int power_iterations,
                                unsigned seed) {
  return randomizedRange(R, gaussianSketch(R.cols(), samples, seed), power_iterations);
}

Eigen::MatrixXd randomizedRange(const Eigen::MatrixXd& R, const Eigen::Ref<const Eigen::MatrixXd>& omega,
                                int power_iterations) {
  Eigen::MatrixXd Q = orthonormalColumns(R * omega);
  for (int it = 0; it < power_iterations; ++it) Q = orthonormalColumns(R * (R.transpose() * Q));
  return Q;
}

}  // namespace stc::linalg
