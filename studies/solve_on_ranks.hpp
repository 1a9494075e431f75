#pragma once
// What changes when a solve runs on several MPI ranks (src/linalg/ranks.hpp; docs/linear_solvers.md,
// "Ranks"), as the command line (`mpirun -np N stcontact solve`) and the Python module
// (`mpirun -np N python3 script.py`) both run it: the backends that can, the outputs rank 0 writes.
#include <string>

#include "stcontact/linalg/ranks.hpp"
#include "stcontact/scene/output_spec.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

/// InputError when the scene's backend cannot run on `ranks`: cholmod runs in one process (auto takes
/// mumps on several ranks); solver.linear_groups must divide the ranks.
void requireBackendForRanks(const Scene& scene, const Ranks& ranks);

/// The outputs rank 0 writes after `result`: the scene's, without frames on several ranks when the
/// strategy holds no displacement (each frame would be a solve of every rank, after the others are
/// done); `note` then says so, else it is left empty.
OutputSpec outputsOnRanks(const Scene& scene, const Ranks& ranks, const SolveResult& result, std::string& note);

}  // namespace stc
