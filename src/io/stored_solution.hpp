#pragma once
// An earlier run's solution as solution.h5 holds it (docs/interface.md, "solution.h5 and
// solution.xdmf"), read back for a check after the run: its contact forces λ (every instant), the
// model it was solved on and the figures it reported. What `stcontact true-error` measures.
#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "stcontact/problem/problem.hpp"

namespace stc {

struct StoredSolution {
  std::string file;        ///< the path it was read from
  std::string solver;      ///< the solver that wrote it
  std::string model_json;  ///< the model solved (Scene::model_json); empty in files before it was kept
  int dimension = 0, contact_nodes = 0, steps = 0;
  long long dofs = 0;
  Eigen::MatrixXd lambda;  ///< d n_C × m: column k the contact forces at instant k (SolveResult's layout)
  double error_estimate = 0.0;  ///< the estimate the run stopped on (NaN: none, as the 0 the incremental solver writes)
  double error = 0.0;           ///< the run's own true error (NaN: none measured)
};

/// Reads `file` (a solution.h5); InputError when it is not one (its "format" attribute) or lacks what
/// is read, MissingFileError when nothing is there.
StoredSolution readStoredSolution(const std::filesystem::path& file);

/// Throws InputError unless `stored` was solved on `problem`, whose model is `model_json`
/// (Scene::model_json; the same scene and overrides, [solver] and [output] aside).
void requireSolvedOn(const StoredSolution& stored, const Problem& problem, const std::string& model_json);

}  // namespace stc
