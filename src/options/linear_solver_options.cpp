#include "stcontact/options/linear_solver_options.hpp"

#include <algorithm>
#include <string>

#include "stcontact/build_config.hpp"

namespace stc {

bool petscBackendsBuilt() {
#if STC_HAVE_PETSC
  return true;
#else
  return false;
#endif
}

void LinearSolverOptions::validate() const {
  validateFields(*this, "solver");
  if ((backend == LinearBackend::Mumps || backend == LinearBackend::CgGamg) && !petscBackendsBuilt())
    throw InputError(
        "solver option linear: this stcontact was built without PETSc, so only \"auto\" and \"cholmod\" are available "
        "(install PETSc, libpetsc-real-dev on Debian, and rebuild: docs/linear_solvers.md)");
}

void LinearSolverOptions::requireGroupsDivide(int ranks) const {
  if (groups > 1 && ranks > 1 && ranks % groups != 0)
    throw InputError("solver option linear_groups = " + std::to_string(groups) + ": must divide the " +
                     std::to_string(ranks) + " ranks (one rank solves alone: 1)");
}

double LinearSolverOptions::residualTolerance(double tolerance) const {
  if (rtol > 0.0) return rtol;
  return std::max(kRtolFloor, kRtolPerTolerance * tolerance);
}

}  // namespace stc
