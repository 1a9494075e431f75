#pragma once
// The MPI ranks of a run (docs/linear_solvers.md, "Ranks"). A process started by an MPI launcher
// (`mpirun -np N stcontact …`) in a build with PETSc is one of N ranks: every rank reads the scene and
// builds the whole problem (the model is replicated), the sparse operators are distributed by rows
// over the ranks and solved together by a PETSc backend, and every rank receives each solution
// whole, so that all take the same steps in the same order (one thread each); rank 0 alone writes.
// Without a launcher: rank 0 of 1, as before ranks existed.
#include <vector>

namespace stc {

struct Ranks {
  int rank = 0;
  int size = 1;
  bool writes() const { return rank == 0; }  ///< the rank that writes the outputs and the messages
};

/// Starts the ranks when an MPI launcher started this process (its environment says how many:
/// OMPI_COMM_WORLD_SIZE, PMI_SIZE) and there is more than one: MPI through PETSc, one thread per
/// rank (setThreadCount(1): the solves of every rank must come in one order). Idempotent. Throws
/// InputError for more than one rank in a build without PETSc.
Ranks startRanks();
/// The ranks started (rank 0 of 1 before startRanks, or without a launcher).
Ranks currentRanks();

/// The ranks started on this machine (the launcher's OMPI_COMM_WORLD_LOCAL_SIZE, MPI_LOCALNRANKS),
/// which share its memory; all of them when it does not say; 1 in one process.
int ranksOnThisMachine();
/// The memory available to this rank: the machine's (MemAvailable) shared by its ranksOnThisMachine().
double availableMemoryOfThisRank();

/// `value` of every rank, in rank order, on every rank: a collective call on several ranks (each must
/// make it, in the same order), {value} on one.
std::vector<double> valuesOfEveryRank(double value);

}  // namespace stc
