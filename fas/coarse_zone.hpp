#pragma once
// The contact zone of the FAS coarse problem (docs/method.md §4, "The coarse step's contact zone"):
// the nodes on which the coarse step's restricted LATIN applies the contact law. A node outside it
// is open at every instant of the local-stage iterate and clear of the obstacle by more than the
// iteration still moves it; the coarse problem takes it open (λ = 0, a linear law), so that
// fas/coarse_step.cpp eliminates its rows exactly and iterates on the zone's rows alone. The coarse
// step's last local stage, its result, is the fine one on every node.
#include <vector>

#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc::fas {

struct CoarseZone {
  std::vector<int> nodes;     ///< nodes of the zone, increasing
  std::vector<int> rows;      ///< their interface rows (d per node)
  std::vector<int> far_rows;  ///< the rows of the other nodes
};

/// From the global-stage iterate `s` (v, λ) and its local stage `hat` (v̂, λ̂): node i is in the
/// zone when, at some instant, λ̂_n > 0 (closed) or its gap g0 + v̂_n is below δ, `delta_scale` times
/// the largest |v_n − v̂_n| over the grid (how far apart the two iterates still are; 0 at
/// convergence). The coarse step takes δ itself; the reduced interface half of it
/// (fas/apriori/reduced_interface.hpp).
CoarseZone coarseZone(const ContactInterface& contact, const InterfaceHistory& s,
                      const InterfaceHistory& hat, double delta_scale = 1.0);

/// Every node of the interface: nothing eliminated (the seed's coarse step).
CoarseZone wholeInterface(const ContactInterface& contact);

}  // namespace stc::fas
