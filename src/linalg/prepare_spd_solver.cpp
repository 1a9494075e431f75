#include "stcontact/linalg/prepare_spd_solver.hpp"

#include <stdexcept>

#include "stcontact/build_config.hpp"

#include "stcontact/core/memory.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/linalg/ranks.hpp"
#if STC_HAVE_PETSC
#include "stcontact/linalg/backends/petsc/petsc_solver.hpp"
#endif

namespace stc {

LinearBackend chooseLinearBackend(const BackendChoice& choice) {
  if (!choice.petsc) return LinearBackend::Cholmod;
  if (choice.ranks > 1) return LinearBackend::Mumps;
  return choice.factor_bytes <= BackendChoice::kFactorMemoryShare * choice.available_bytes ? LinearBackend::Cholmod
                                                                                           : LinearBackend::CgGamg;
}


std::unique_ptr<SpdSolver> prepareSpdSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                            const LinearSolverOptions& requested, const SpdSolverHints& hints) {
  LinearSolverOptions options = requested;
  if (requested.backend == LinearBackend::Auto) {
    const int ranks = currentRanks().size;
    if (!petscBackendsBuilt() || ranks > 1) {
      options.backend = chooseLinearBackend({0.0, 0.0, ranks, petscBackendsBuilt()});
    } else {  // CHOLMOD unless its symbolic analysis finds the factor too large for the memory left
      try {
        return std::make_unique<CholmodFactor>(A, what, hints.trailing, hints.min_work,
                                               BackendChoice::kFactorMemoryShare * availableMemoryBytes());
      } catch (const CholmodFactor::TooLarge&) {
        options.backend = LinearBackend::CgGamg;
      }
    }
  }
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
