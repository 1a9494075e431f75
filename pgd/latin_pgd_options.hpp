#pragma once
// Options of `latin-pgd`: LATIN (docs/method.md §2) whose global stage is solved in separated form
// with its error controlled (docs/method.md §5; pgd/controlled_global_stage.hpp).
#include "stcontact/latin/latin_options.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"

namespace stc::pgd {

struct LatinPgdOptions {
  latin::LatinOptions latin;       ///< tolerance, iteration limit, stagnation, relaxation
  ControlledStageOptions stage;    ///< the control of the separated global stage
  bool spatial_modes = true;       ///< return SolveResult::spatial_modes (one product after the last iteration)

  void validate() const {
    latin.validate();
    stage.validate();
  }
};

}  // namespace stc::pgd
