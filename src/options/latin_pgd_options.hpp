#pragma once
// Options of `latin-pgd`: LATIN (docs/method.md §2) whose global stage is solved in separated form
// with its error controlled (docs/method.md §5; pgd/controlled_global_stage.hpp).
#include "stcontact/options/latin_options.hpp"
#include "stcontact/options/separated_stage_options.hpp"

namespace stc::pgd {

struct LatinPgdOptions {
  latin::LatinOptions latin;    ///< stopping, relaxation
  ControlledStageOptions stage; ///< the control of the separated global stage

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    latin::LatinOptions::fields(o.latin, visit);
    ControlledStageOptions::fields(o.stage, visit);
  }
  void validate() const {
    latin.validate();
    stage.validate();
  }
};

}  // namespace stc::pgd
