#include "stcontact/linalg/prepare_spd_solver.hpp"

#include <stdexcept>

#include "stcontact/build_config.hpp"

#include "stcontact/linalg/backends/cholmod_factor.hpp"
#if STC_HAVE_PETSC
#include "stcontact/linalg/backends/petsc/petsc_solver.hpp"
#endif

namespace stc {

std::unique_ptr<SpdSolver> prepareSpdSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                            const LinearSolverOptions& options, const SpdSolverHints& hints) {
  if (options.backend == LinearBackend::Cholmod)
    return std::make_unique<CholmodFactor>(A, what, hints.trailing, hints.min_work);
#if STC_HAVE_PETSC
  return preparePetscSolver(A, what, options, hints.near_null_space);
#else
  options.validate();  // the InputError naming solver.linear
  throw std::logic_error("prepareSpdSolver: a PETSc backend in a build without PETSc");
#endif
}

}  // namespace stc
