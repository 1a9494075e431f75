// stcontact._core.ranks and the ranks of a call (docs/python.md, "On several MPI ranks"): a script
// started by `mpirun -np N` solves on N ranks as `mpirun -np N stcontact solve` does; every rank
// makes the same calls in the same order and receives the whole result, rank 0 alone writes `out`.
#include <pybind11/stl.h>

#include "stcontact/core/input_error.hpp"
#include "stcontact/python/bindings.hpp"

namespace stc::python {

Ranks ranksForCall(std::optional<int> threads) {
  const Ranks ranks = startRanks();
  if (ranks.size > 1 && threads && *threads != 1)
    throw InputError("threads=" + std::to_string(*threads) + " on " + std::to_string(ranks.size) +
                     " MPI ranks: each rank runs one thread (its solves must come in the order of the others')");
  return ranks;
}

void requireOneProcess(const std::string& what) {
  const Ranks ranks = startRanks();
  if (ranks.size > 1)
    throw InputError(what + " runs in one process (started as " + std::to_string(ranks.size) +
                     " MPI ranks); only solve runs on several");
}

void bindRanks(py::module_& module) {
  module.def(
      "ranks",
      [] {
        const Ranks ranks = startRanks();
        return py::make_tuple(ranks.rank, ranks.size);
      },
      "(rank, size): this process's MPI rank and how many there are, the ranks started when an MPI "
      "launcher started the interpreter (mpirun -np N); (0, 1) otherwise.");
}

}  // namespace stc::python
