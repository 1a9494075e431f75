#include "stcontact/options/fas_apriori_options.hpp"

#include <cmath>

namespace stc::fas {

void AprioriBasisOptions::validate() const {
  constexpr const char* kOwner = "a priori basis";
  validateFields(*this, kOwner);
  requireOption(modes + increment_modes >= 1, kOwner, "pgd_max_modes + pgd_increment_modes", modes + increment_modes,
                "must be >= 1 (an empty coarse space)");
}

double ReducedInterfaceOptions::searchScaleOn(int nodes, int dimension) const {
  if (dimension != 2 || nodes <= kSearchNodes || search_growth == 0.0) return 1.0;
  return std::pow(static_cast<double>(nodes) / kSearchNodes, search_growth);
}

}  // namespace stc::fas
