#include "stcontact/linalg/ranks.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <string>

#include "stcontact/build_config.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/core/threads.hpp"
#if STC_HAVE_PETSC
#include "stcontact/linalg/backends/petsc/petsc_solver.hpp"
#endif

namespace stc {
namespace {

Ranks started;

// How many ranks the launcher started (Open MPI's mpirun, MPICH's hydra); 1 without one.
int launchedRanks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
  return 1;
}

}  // namespace

Ranks startRanks() {
  static std::once_flag once;
  std::call_once(once, [] {
    const int launched = launchedRanks();
    if (launched <= 1) return;
#if STC_HAVE_PETSC
    started = petscRanks();
    setThreadCount(1);
#else
    throw InputError("started as " + std::to_string(launched) +
                     " MPI ranks, but this stcontact was built without PETSc, which ranks need: run it as one "
                     "process, or build it with PETSc (docs/linear_solvers.md)");
#endif
  });
  return started;
}

Ranks currentRanks() { return started; }

int ranksOnThisMachine() {
  if (started.size <= 1) return 1;
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
    if (const char* value = std::getenv(name)) return std::clamp(std::atoi(value), 1, started.size);
  return started.size;
}

double availableMemoryOfThisRank() { return availableMemoryBytes() / ranksOnThisMachine(); }

std::vector<double> valuesOfEveryRank(double value) {
#if STC_HAVE_PETSC
  if (started.size > 1) return petscAllGather(value);
#endif
  return {value};
}

}  // namespace stc
