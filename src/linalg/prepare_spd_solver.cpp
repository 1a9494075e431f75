#include "stcontact/linalg/prepare_spd_solver.hpp"

#include <stdexcept>

#include "stcontact/build_config.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/linalg/ranks.hpp"
#if STC_HAVE_PETSC
#include "stcontact/linalg/backends/petsc/petsc_solver.hpp"
#endif

namespace stc {

AutoBackend autoBackend(int ranks, bool petsc, double available_bytes) {
  if (!petsc) return {LinearBackend::Cholmod, CholmodFactor::kNoMemoryBound};
  return {ranks > 1 ? LinearBackend::Mumps : LinearBackend::Cholmod, kFactorMemoryShare * available_bytes};
}

std::unique_ptr<SpdSolver> prepareSpdSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                            const LinearSolverOptions& requested, const SpdSolverHints& hints) {
  LinearSolverOptions options = requested;
  double max_factor_bytes = CholmodFactor::kNoMemoryBound;
  if (requested.backend == LinearBackend::Auto) {
    const AutoBackend choice =
        autoBackend(currentRanks().size, petscBackendsBuilt(), availableMemoryOfThisRank());
    options.backend = choice.backend;
    max_factor_bytes = choice.max_factor_bytes;
  }
  if (options.backend == LinearBackend::Cholmod) try {
      return std::make_unique<CholmodFactor>(A, what, hints.trailing, hints.min_work, max_factor_bytes);
    } catch (const FactorTooLarge&) {  // only under auto's bound, which PETSc's presence sets
      options.backend = LinearBackend::CgGamg;
    }
#if STC_HAVE_PETSC
  if (options.backend == LinearBackend::Mumps) try {
      return preparePetscSolver(A, what, options, hints.near_null_space, max_factor_bytes);
    } catch (const FactorTooLarge&) {  // only under auto's bound
      options.backend = LinearBackend::CgGamg;
    }
  return preparePetscSolver(A, what, options, hints.near_null_space);
#else
  options.validate();  // the InputError naming solver.linear
  throw std::logic_error("prepareSpdSolver: a PETSc backend in a build without PETSc");
#endif
}

}  // namespace stc
