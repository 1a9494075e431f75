#include "stcontact/options/fas_apriori_options.hpp"

namespace stc::fas {

void AprioriBasisOptions::validate() const {
  constexpr const char* kOwner = "a priori basis";
  validateFields(*this, kOwner);
  requireOption(modes + increment_modes >= 1, kOwner, "pgd_max_modes + pgd_increment_modes", modes + increment_modes,
                "must be >= 1 (an empty coarse space)");
}

}  // namespace stc::fas
