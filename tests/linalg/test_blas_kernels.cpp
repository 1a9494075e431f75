// OpenBLAS's kernel choice (src/linalg/blas_kernels.hpp): only the generic fallback is replaced,
// the switch leaves no fallback the processor could beat, and products on the kernels switched to
// agree with Eigen's own. Each ctest case runs in a process of its own, so the switch is this
// test's.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cstdio>
#include <cstdlib>
#include <tuple>

#include "stcontact/linalg/blas_kernels.hpp"

// OpenBLAS's dgemm, declared as Eigen's Eigen/src/misc/blas.h does (EIGEN_USE_BLAS builds include
// it).
extern "C" int dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                      const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                      const double* beta, double* c, const int* ldc);

namespace {

bool userChoseKernels() { return std::getenv("OPENBLAS_CORETYPE") != nullptr; }

}  // namespace

TEST(BlasKernels, OnlyTheGenericFallbackIsReplaced) {
  for (const char* known : {"Zen", "SkylakeX", "Haswell", "Cooperlake", "Nehalem", "Sandybridge", ""})
    EXPECT_EQ(stc::linalg::fasterBlasKernels(known), "") << known;
  const std::string instead = stc::linalg::fasterBlasKernels("Prescott");
  EXPECT_TRUE(instead.empty() || instead == "SkylakeX" || instead == "Haswell") << instead;
}

TEST(BlasKernels, TheSwitchLeavesNoFallbackTheProcessorCouldBeat) {
  if (userChoseKernels()) GTEST_SKIP() << "OPENBLAS_CORETYPE is set: the user's choice stands";
  const std::string before = stc::linalg::blasKernels();
  const std::string after = stc::linalg::preferFastBlasKernels();
  std::printf("[ measured ] OpenBLAS kernels: %s at load, %s after the switch\n", before.c_str(),
              after.c_str());
  EXPECT_EQ(after, stc::linalg::blasKernels());
  EXPECT_FALSE(after.empty());
  EXPECT_EQ(stc::linalg::fasterBlasKernels(after), "");
  if (!stc::linalg::fasterBlasKernels(before).empty()) EXPECT_NE(after, before);
}

TEST(BlasKernels, ProductsOnTheChosenKernelsAgreeWithEigensOwn) {
  stc::linalg::preferFastBlasKernels();
  // The coarse step's shapes (r × d n_C by d n_C × m) and a square one, through OpenBLAS's dgemm
  // itself, against Eigen's coefficient-based product.
  for (const auto& [m, k, n] : {std::tuple{45, 1602, 201}, std::tuple{300, 300, 300}, std::tuple{7, 3, 5}}) {
    std::srand(11);
    const Eigen::MatrixXd A = Eigen::MatrixXd::Random(m, k), B = Eigen::MatrixXd::Random(k, n);
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(m, n);
    const double one = 1.0, zero = 0.0;
    dgemm_("N", "N", &m, &n, &k, &one, A.data(), &m, B.data(), &k, &zero, C.data(), &m);
    const Eigen::MatrixXd expected = A.lazyProduct(B);
    EXPECT_LE((C - expected).norm(), 1e-13 * A.norm() * B.norm()) << m << " x " << k << " x " << n;
  }
}
