#include "stcontact/contact/contact_state.hpp"

#include <cmath>

namespace stc {

const char* toString(ContactState state) {
  switch (state) {
    case ContactState::Open: return "open";
    case ContactState::Stick: return "stick";
    case ContactState::Slip: return "slip";
  }
  return "unknown";
}

ContactState classifyContact(double lambda_n, double lambda_t, double slip, double mu, double force_scale,
                             double length_scale) {
  namespace tol = contact_state_tolerance;
  if (lambda_n <= tol::open_force * force_scale) return ContactState::Open;
  const bool on_cone = std::abs(lambda_t) >= mu * lambda_n * (1.0 - tol::cone);
  const bool moving = std::abs(slip) > tol::slip * length_scale;
  return on_cone && moving ? ContactState::Slip : ContactState::Stick;
}

}  // namespace stc
