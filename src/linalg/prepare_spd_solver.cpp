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

AutoBackend autoBackend(int ranks, bool petsc, double available_bytes) {
  if (!petsc) return {LinearBackend::Cholmod, available_bytes, false};
  return {ranks > 1 ? LinearBackend::Mumps : LinearBackend::Cholmod, kFactorMemoryShare * available_bytes, true};
}

InputError factorRefused(LinearBackend backend, const FactorTooLarge& refused) {
  return InputError("solver.linear = \"" + std::string(nameOf(backend)) + "\": " + refused.what() +
                    " (what this rank may use): \"cg-gamg\" needs no factor (a build with PETSc)");
}

std::unique_ptr<SpdSolver> prepareSpdSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                            const LinearSolverOptions& requested, const SpdSolverHints& hints) {
  LinearSolverOptions options = requested;
  const double available = availableMemoryOfThisRank();
  // A direct factor asked for by name may take all the memory the rank has; beyond, it is refused.
  AutoBackend choice{requested.backend, available, false};
  if (requested.backend == LinearBackend::Auto) choice = autoBackend(currentRanks().size, petscBackendsBuilt(), available);
  options.backend = choice.backend;
  if (options.backend == LinearBackend::Cholmod) try {
      return std::make_unique<CholmodFactor>(A, what, hints.trailing, hints.min_work, choice.max_factor_bytes);
    } catch (const FactorTooLarge& refused) {
      if (!choice.gives_way) throw factorRefused(options.backend, refused);
      options.backend = LinearBackend::CgGamg;
    }
#if STC_HAVE_PETSC
  if (options.backend == LinearBackend::Mumps) try {
      return preparePetscSolver(A, what, options, hints.near_null_space, choice.max_factor_bytes);
    } catch (const FactorTooLarge& refused) {
      if (!choice.gives_way) throw factorRefused(options.backend, refused);
      options.backend = LinearBackend::CgGamg;
    }
  return preparePetscSolver(A, what, options, hints.near_null_space);
#else
  options.validate();  // the InputError naming solver.linear
  throw std::logic_error("prepareSpdSolver: a PETSc backend in a build without PETSc");
#endif
}

}  // namespace stc
