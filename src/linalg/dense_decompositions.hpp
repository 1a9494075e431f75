#pragma once
// The dense decompositions the solvers use on small matrices (Gram matrices, projected histories),
// each one instantiated in dense_decompositions.cpp alone. Eigen's SVDs and symmetric eigensolver
// are heavy templates: each file that instantiated them took one to two minutes to compile in the
// sanitizer build, and eight did.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace stc::linalg {

/// Q of the Householder QR of Y (LAPACK's dgeqrf and dorgqr from OpenBLAS when Eigen's products use
/// it, Eigen::HouseholderQR otherwise), Y.cols() orthonormal columns: for every k the first k span
/// Y's first k when those are independent.
Eigen::MatrixXd orthonormalColumns(const Eigen::MatrixXd& Y);

/// An orthonormal basis (n × (n − p)) of the complement of the range of Q (n × p, p ≤ n, orthonormal
/// columns): the last n − p columns of the full Q of Q's Householder QR, [0; I] with the reflectors
/// applied (LAPACK's dgeqrf and dormqr where orthonormalColumns uses LAPACK, Eigen otherwise).
Eigen::MatrixXd orthonormalComplement(const Eigen::MatrixXd& Q);

/// Eigenpairs of the symmetric M (Eigen::SelfAdjointEigenSolver, which reads its lower triangle),
/// eigenvalues ascending, eigenvector j in column j. `converged` is false when the QR iterations did not.
struct SymmetricEigen {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  bool converged = true;
};
SymmetricEigen symmetricEigen(const Eigen::MatrixXd& M);

/// Columns spanning V's range, orthonormal in the SPD product M (YᵀMY = I): Y = V Q D^{-1/2} from
/// the eigenpairs (D, Q) of the Gram matrix VᵀMV, leaving out directions whose eigenvalue is below
/// `drop` times the largest (dependent columns). n × 0 when V has no column.
Eigen::MatrixXd orthonormalIn(const Eigen::MatrixXd& V, const Eigen::SparseMatrix<double>& M, double drop = 1e-12);

enum class SvdMethod {
  jacobi,              ///< two-sided Jacobi (Eigen::JacobiSVD): accurate, O(n³) with a large constant
  divide_and_conquer,  ///< Eigen::BDCSVD: bidiagonalisation then divide and conquer (Jacobi below 16 columns)
  /// LAPACK's dgesvd (QR, bidiagonalisation, implicit QR iteration) from OpenBLAS on the taller of M
  /// and Mᵀ when Eigen's products use OpenBLAS, Jacobi otherwise: singular values to ε σ_1, like
  /// divide and conquer. On the range finders' projected histories (25 to 64 rows, 201 and 2001
  /// columns) 0.31 to 0.97 of Jacobi's time (bench/bench_dense.cpp).
  qr_iteration,
  /// LAPACK's dgesdd (divide and conquer) on the R of the taller of M and Mᵀ when Eigen's products
  /// use OpenBLAS, Eigen::BDCSVD otherwise: singular values to ε σ_1. For the large ones: on a 950 ×
  /// 2001 history asked for its left vectors, 0.4 of qr_iteration's time.
  lapack_divide_and_conquer,
};
enum SvdVectors : unsigned { kValuesOnly = 0, kThinU = 1, kThinV = 2 };

/// M = U diag(values) Vᵀ, values decreasing; U and V thin and filled only when asked for.
struct Svd {
  Eigen::VectorXd values;
  Eigen::MatrixXd U, V;
};
Svd singularValueDecomposition(const Eigen::MatrixXd& M, SvdMethod method, unsigned vectors);

/// A rows × cols matrix of independent standard normal entries, filled column by column from
/// std::mt19937(seed): the same seed gives the same sketch on every platform with the same library.
Eigen::MatrixXd gaussianSketch(Eigen::Index rows, Eigen::Index cols, unsigned seed);

/// Orthonormal basis (R.rows() × samples) of the approximate leading range of R: randomized range
/// finder with `power_iterations` subspace iterations (Halko, Martinsson & Tropp 2011, algs. 4.1
/// and 4.4), Q = orth(R Ω), then Q = orth(R (Rᵀ Q)) each iteration, Ω = gaussianSketch(R.cols(),
/// samples, seed).
Eigen::MatrixXd randomizedRange(const Eigen::MatrixXd& R, Eigen::Index samples, int power_iterations,
                                unsigned seed);
/// The same from a given sketch Ω (R.cols() × samples).
Eigen::MatrixXd randomizedRange(const Eigen::MatrixXd& R, const Eigen::Ref<const Eigen::MatrixXd>& omega,
                                int power_iterations);

}  // namespace stc::linalg
