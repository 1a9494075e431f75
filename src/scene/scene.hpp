#pragma once
// A validated scene: the input as read from TOML (docs/interface.md "Scene file"), nothing computed:
// the model (model_spec.hpp), the strategy and every strategy's options ([solver]), the outputs.
#include <string>

#include "stcontact/options/solver_spec.hpp"
#include "stcontact/scene/model_spec.hpp"
#include "stcontact/scene/output_spec.hpp"

namespace stc {

struct Scene : ModelSpec {
  SolverSpec solver;             ///< [solver]: the strategy and every strategy's options (src/options/)
  OutputSpec output;
  std::string parameters_json;  ///< the scene as read (overrides applied), as a JSON object
  /// The same without [solver] and [output]: what fixes the exact solution (mesh, material,
  /// contact, obstacle, time, loads), recorded in solution.h5 so that a later check of its true
  /// error (`stcontact true-error`) knows the scene given is the one solved.
  std::string model_json;
};

/// Every key of the scene's [solver] table, in the order the reader walks them: the search
/// direction's (the model's, src/options/search_direction_options.hpp), then every strategy's
/// (SolverSpec). `Self` is Scene or const Scene.
template <class Self, class Visit>
void solverTableFields(Self& scene, Visit&& visit) {
  SearchDirectionOptions::fields(scene.search_direction, visit);
  SolverSpec::fields(scene.solver, visit);
}

/// The [solver] table's fields against their ranges (what the reader checks, for a Scene built in
/// code): InputError naming the first one out of its range.
inline void validateSolverTable(const Scene& scene) {
  scene.search_direction.validate();
  scene.solver.validate();
}

}  // namespace stc
