#include "stcontact/fas/coarse_zone.hpp"

#include <algorithm>
#include <cmath>

namespace stc::fas {
namespace {

// Sorts node i's d rows into the zone's or the far ones.
void addNode(int d, int i, bool in_zone, CoarseZone& zone) {
  if (in_zone) zone.nodes.push_back(i);
  for (int a = 0; a < d; ++a) (in_zone ? zone.rows : zone.far_rows).push_back(d * i + a);
}

}  // namespace

CoarseZone coarseZone(const ContactInterface& contact, const InterfaceHistory& s,
                      const InterfaceHistory& hat, double delta_scale) {
  const int d = contact.dimension, n = contact.size();
  const Eigen::Index m = hat.v.cols();
  // Instant by instant: the fields are stored by column, a node's row is d n_C doubles apart from
  // one instant to the next (on 401 nodes × 2001 instants, walking the rows took 7 % of a solve).
  double delta = 0.0;
  for (Eigen::Index j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) delta = std::max(delta, std::abs(s.v(d * i, j) - hat.v(d * i, j)));
  delta *= delta_scale;
  std::vector<char> in_zone(static_cast<size_t>(n), 0);
  for (Eigen::Index j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int row = d * i;
      if (hat.lambda(row, j) > 0.0 || contact.initial_gap[i] + hat.v(row, j) < delta)
        in_zone[static_cast<size_t>(i)] = 1;
    }
  CoarseZone zone;
  for (int i = 0; i < n; ++i) addNode(d, i, in_zone[static_cast<size_t>(i)] != 0, zone);
  return zone;
}

CoarseZone wholeInterface(const ContactInterface& contact) {
  CoarseZone zone;
  for (int i = 0; i < contact.size(); ++i) addNode(contact.dimension, i, true, zone);
  return zone;
}

}  // namespace stc::fas
